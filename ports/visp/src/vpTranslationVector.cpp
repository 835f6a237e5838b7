// SPDX-License-Identifier: BSD-3-Clause
/// vpTranslationVector's arithmetic, conversions, skew matrix and cross product.
#include "visp3/core/vpTranslationVector.h"

#include <cmath>

#include "visp3/core/vpHomogeneousMatrix.h"
#include "visp3/core/vpPoseVector.h"

inline namespace edgetrack_ports {

vpTranslationVector vpTranslationVector::buildFrom(real tx, real ty, real tz) {
  set(tx, ty, tz);
  return *this;
}

vpTranslationVector vpTranslationVector::buildFrom(const vpHomogeneousMatrix& M) {
  set(M[0][3], M[1][3], M[2][3]);
  return *this;
}

vpTranslationVector vpTranslationVector::buildFrom(const vpPoseVector& p) {
  set(p[0], p[1], p[2]);
  return *this;
}

vpTranslationVector vpTranslationVector::buildFrom(const vpColVector& v) {
  set(v[0], v[1], v[2]);
  return *this;
}

vpTranslationVector vpTranslationVector::operator+(const vpTranslationVector& t) const {
  return vpTranslationVector(data_[0] + t[0], data_[1] + t[1], data_[2] + t[2]);
}

vpTranslationVector vpTranslationVector::operator-(const vpTranslationVector& t) const {
  return vpTranslationVector(data_[0] - t[0], data_[1] - t[1], data_[2] - t[2]);
}

vpTranslationVector vpTranslationVector::operator-() const { return vpTranslationVector(-data_[0], -data_[1], -data_[2]); }

vpTranslationVector vpTranslationVector::operator*(real x) const {
  return vpTranslationVector(data_[0] * x, data_[1] * x, data_[2] * x);
}

vpTranslationVector vpTranslationVector::operator/(real x) const {
  return vpTranslationVector(data_[0] / x, data_[1] / x, data_[2] / x);
}

vpTranslationVector& vpTranslationVector::operator*=(real x) {
  for (real& v : data_) v *= x;
  return *this;
}

vpTranslationVector& vpTranslationVector::operator/=(real x) {
  for (real& v : data_) v /= x;
  return *this;
}

vpTranslationVector& vpTranslationVector::operator=(real x) {
  for (real& v : data_) v = x;
  return *this;
}

real vpTranslationVector::frobeniusNorm() const {
  using std::sqrt;
  return sqrt(sumSquare());
}

vpMatrix vpTranslationVector::skew(const vpTranslationVector& t) {
  vpMatrix M(3, 3);
  M[0][1] = -t[2];
  M[0][2] = t[1];
  M[1][0] = t[2];
  M[1][2] = -t[0];
  M[2][0] = -t[1];
  M[2][1] = t[0];
  return M;
}

vpTranslationVector vpTranslationVector::cross(const vpTranslationVector& a, const vpTranslationVector& b) {
  return vpTranslationVector(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

vpTranslationVector::operator vpColVector() const {
  vpColVector v(3);
  for (unsigned int k = 0; k < 3; ++k) v[k] = data_[k];
  return v;
}

}  // inline namespace edgetrack_ports
