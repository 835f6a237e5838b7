// SPDX-License-Identifier: BSD-3-Clause
/// vpRotationMatrix: Rodrigues' formula from theta u, products, transpose and the orthonormality test.
#include "visp3/core/vpRotationMatrix.h"

#include <cmath>

#include "visp3/core/vpHomogeneousMatrix.h"
#include "visp3/core/vpMath.h"
#include "visp3/core/vpPoseVector.h"
#include "visp3/core/vpThetaUVector.h"

inline namespace edgetrack_ports {

void vpRotationMatrix::eye() {
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c) data_[r][c] = r == c ? real(1) : real(0);
}

vpRotationMatrix vpRotationMatrix::buildFrom(const vpHomogeneousMatrix& M) {
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c) data_[r][c] = M[r][c];
  return *this;
}

vpRotationMatrix vpRotationMatrix::buildFrom(const vpThetaUVector& v) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const real theta = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const real si = sin(theta), co = cos(theta);
  const real sinc = vpMath::sinc(si, theta), mcosc = vpMath::mcosc(co, theta);
  data_[0][0] = co + mcosc * v[0] * v[0];
  data_[0][1] = -sinc * v[2] + mcosc * v[0] * v[1];
  data_[0][2] = sinc * v[1] + mcosc * v[0] * v[2];
  data_[1][0] = sinc * v[2] + mcosc * v[1] * v[0];
  data_[1][1] = co + mcosc * v[1] * v[1];
  data_[1][2] = -sinc * v[0] + mcosc * v[1] * v[2];
  data_[2][0] = -sinc * v[1] + mcosc * v[2] * v[0];
  data_[2][1] = sinc * v[0] + mcosc * v[2] * v[1];
  data_[2][2] = co + mcosc * v[2] * v[2];
  return *this;
}

vpRotationMatrix vpRotationMatrix::buildFrom(const vpPoseVector& p) { return buildFrom(p.getThetaUVector()); }

vpRotationMatrix vpRotationMatrix::buildFrom(real tux, real tuy, real tuz) {
  return buildFrom(vpThetaUVector(tux, tuy, tuz));
}

vpColVector vpRotationMatrix::getCol(unsigned int j) const {
  vpColVector v(3);
  for (unsigned int r = 0; r < 3; ++r) v[r] = data_[r][j];
  return v;
}

vpThetaUVector vpRotationMatrix::getThetaUVector() { return vpThetaUVector(*this); }

vpRotationMatrix vpRotationMatrix::t() const {
  vpRotationMatrix T;
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c) T[c][r] = data_[r][c];
  return T;
}

bool vpRotationMatrix::isARotationMatrix(real threshold) const {
  using std::abs;
  const vpRotationMatrix RtR = t() * (*this);
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c)
      if (abs(RtR[r][c] - (r == c ? real(1) : real(0))) > threshold) return false;
  return true;
}

vpRotationMatrix& vpRotationMatrix::operator=(const vpMatrix& M) {
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c) data_[r][c] = M[r][c];
  return *this;
}

vpTranslationVector vpRotationMatrix::operator*(const vpTranslationVector& t) const {
  vpTranslationVector p;
  for (unsigned int r = 0; r < 3; ++r) p[r] = data_[r][0] * t[0] + data_[r][1] * t[1] + data_[r][2] * t[2];
  return p;
}

vpRotationMatrix vpRotationMatrix::operator*(const vpRotationMatrix& R) const {
  vpRotationMatrix P;
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c) P[r][c] = data_[r][0] * R[0][c] + data_[r][1] * R[1][c] + data_[r][2] * R[2][c];
  return P;
}

vpMatrix vpRotationMatrix::operator*(const vpMatrix& M) const { return vpMatrix(*this) * M; }

vpColVector vpRotationMatrix::operator*(const vpColVector& v) const {
  vpColVector p(3);
  for (unsigned int r = 0; r < 3; ++r) p[r] = data_[r][0] * v[0] + data_[r][1] * v[1] + data_[r][2] * v[2];
  return p;
}

vpRotationMatrix vpRotationMatrix::operator*(real x) const {
  vpRotationMatrix P(*this);
  return P *= x;
}

vpRotationMatrix& vpRotationMatrix::operator*=(real x) {
  for (auto& row : data_)
    for (real& v : row) v *= x;
  return *this;
}

vpRotationMatrix::operator vpMatrix() const {
  vpMatrix M(3, 3);
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c) M[r][c] = data_[r][c];
  return M;
}

}  // inline namespace edgetrack_ports
