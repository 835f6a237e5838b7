// SPDX-License-Identifier: BSD-3-Clause
/// vpHomogeneousMatrix: composition, inverse, and the conversions to and from its parts.
#include "visp3/core/vpHomogeneousMatrix.h"

#include <cmath>
#include <cstdio>

#include "visp3/core/vpPoseVector.h"

inline namespace edgetrack_ports {

void vpHomogeneousMatrix::eye() {
  for (unsigned int r = 0; r < 4; ++r)
    for (unsigned int c = 0; c < 4; ++c) data_[r][c] = r == c ? real(1) : real(0);
}

void vpHomogeneousMatrix::insert(const vpRotationMatrix& R) {
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 3; ++c) data_[r][c] = R[r][c];
}

void vpHomogeneousMatrix::insert(const vpThetaUVector& tu) { insert(vpRotationMatrix(tu)); }

void vpHomogeneousMatrix::insert(const vpTranslationVector& t) {
  for (unsigned int r = 0; r < 3; ++r) data_[r][3] = t[r];
}

void vpHomogeneousMatrix::buildFrom(const vpTranslationVector& t, const vpRotationMatrix& R) {
  eye();
  insert(R);
  insert(t);
}

void vpHomogeneousMatrix::buildFrom(const vpTranslationVector& t, const vpThetaUVector& tu) {
  buildFrom(t, vpRotationMatrix(tu));
}

void vpHomogeneousMatrix::buildFrom(const vpPoseVector& p) {
  buildFrom(p.getTranslationVector(), p.getThetaUVector());
}

void vpHomogeneousMatrix::buildFrom(real tx, real ty, real tz, real tux, real tuy, real tuz) {
  buildFrom(vpTranslationVector(tx, ty, tz), vpThetaUVector(tux, tuy, tuz));
}

vpColVector vpHomogeneousMatrix::getCol(unsigned int j) const {
  vpColVector v(4);
  for (unsigned int r = 0; r < 4; ++r) v[r] = data_[r][j];
  return v;
}

vpRotationMatrix vpHomogeneousMatrix::getRotationMatrix() const { return vpRotationMatrix(*this); }

vpThetaUVector vpHomogeneousMatrix::getThetaUVector() const { return vpThetaUVector(getRotationMatrix()); }

vpTranslationVector vpHomogeneousMatrix::getTranslationVector() const { return vpTranslationVector(*this); }

vpHomogeneousMatrix vpHomogeneousMatrix::inverse() const {
  const vpRotationMatrix Rt = getRotationMatrix().t();
  return vpHomogeneousMatrix(-(Rt * getTranslationVector()), Rt);
}

bool vpHomogeneousMatrix::isAnHomogeneousMatrix(real threshold) const {
  using std::abs;
  if (!getRotationMatrix().isARotationMatrix(threshold)) return false;
  for (unsigned int c = 0; c < 3; ++c)
    if (abs(data_[3][c]) > threshold) return false;
  return abs(data_[3][3] - real(1)) <= threshold;
}

vpHomogeneousMatrix vpHomogeneousMatrix::operator*(const vpHomogeneousMatrix& M) const {
  vpHomogeneousMatrix P;
  for (unsigned int r = 0; r < 4; ++r)
    for (unsigned int c = 0; c < 4; ++c) {
      real s = 0;
      for (unsigned int k = 0; k < 4; ++k) s += data_[r][k] * M[k][c];
      P[r][c] = s;
    }
  return P;
}

vpColVector vpHomogeneousMatrix::operator*(const vpColVector& v) const {
  vpColVector p(4);
  for (unsigned int r = 0; r < 4; ++r) {
    real s = 0;
    for (unsigned int k = 0; k < 4; ++k) s += data_[r][k] * v[k];
    p[r] = s;
  }
  return p;
}

vpTranslationVector vpHomogeneousMatrix::operator*(const vpTranslationVector& t) const {
  return getRotationMatrix() * t + getTranslationVector();
}

void vpHomogeneousMatrix::print() const {
  for (unsigned int r = 0; r < 4; ++r) {
    for (unsigned int c = 0; c < 4; ++c) std::printf("%s%g", c == 0 ? "" : "  ", static_cast<double>(data_[r][c]));
    std::printf("\n");
  }
}

}  // inline namespace edgetrack_ports
