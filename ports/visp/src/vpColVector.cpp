// SPDX-License-Identifier: BSD-3-Clause
/// vpColVector's element-wise arithmetic; sizes must match (as upstream, which throws).
#include "visp3/core/vpColVector.h"

inline namespace edgetrack_ports {

vpColVector vpColVector::operator+(const vpColVector& v) const {
  vpColVector r(*this);
  return r += v;
}

vpColVector vpColVector::operator-(const vpColVector& v) const {
  vpColVector r(*this);
  return r -= v;
}

vpColVector vpColVector::operator-() const {
  vpColVector r(getRows());
  for (unsigned int k = 0; k < getRows(); ++k) r[k] = -data_[k];
  return r;
}

vpColVector vpColVector::operator*(real s) const {
  vpColVector r(*this);
  return r *= s;
}

vpColVector vpColVector::operator/(real s) const {
  vpColVector r(*this);
  return r /= s;
}

vpColVector& vpColVector::operator+=(const vpColVector& v) {
  for (unsigned int k = 0; k < getRows(); ++k) data_[k] += v[k];
  return *this;
}

vpColVector& vpColVector::operator-=(const vpColVector& v) {
  for (unsigned int k = 0; k < getRows(); ++k) data_[k] -= v[k];
  return *this;
}

vpColVector& vpColVector::operator*=(real s) {
  for (real& x : data_) x *= s;
  return *this;
}

vpColVector& vpColVector::operator/=(real s) {
  for (real& x : data_) x /= s;
  return *this;
}

real vpColVector::sum() const {
  real s = 0;
  for (const real& x : data_) s += x;
  return s;
}

real vpColVector::sumSquare() const {
  real s = 0;
  for (const real& x : data_) s += x * x;
  return s;
}

real vpColVector::dotProd(const vpColVector& a, const vpColVector& b) {
  real s = 0;
  for (unsigned int k = 0; k < a.getRows(); ++k) s += a[k] * b[k];
  return s;
}

}  // inline namespace edgetrack_ports
