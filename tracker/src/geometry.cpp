// SPDX-License-Identifier: BSD-3-Clause
/// Norms and matrix products for the geometry value types.
#include "edgetrack/geometry.h"

#include <cmath>
#include <limits>

namespace edgetrack {

namespace {

/// Fixed point squares with the absolute resolution of its fraction bits: in S47.16 a 10 mm
/// component squared is 6.5 steps of 2^-16, and its square root keeps 2 digits. A short vector
/// is therefore doubled (exact in fixed point) until its largest component reaches 1, and its
/// length halved back after the square root; floating point needs none of this.
constexpr bool kScaleShortVectors = !std::numeric_limits<real>::is_iec559;
constexpr int kMostDoublings = 30;  // more than any fixed-point real needs from one step (2^-23) to 1

real largest_magnitude(const real& a, const real& b, const real& c) {
  using std::fabs;
  const real x = fabs(a), y = fabs(b), z = fabs(c);
  return x > y ? (x > z ? x : z) : (y > z ? y : z);
}

/// How many doublings bring `largest` (> 0) to 1 or more, at most kMostDoublings.
int doublings_to_one(real largest) {
  int count = 0;
  for (; largest < real(1) && count < kMostDoublings; ++count) largest = largest + largest;
  return count;
}

real doubled(real value, int times) {
  for (int k = 0; k < times; ++k) value = value + value;
  return value;
}

real halved(real value, int times) {
  for (int k = 0; k < times; ++k) value = value * real(0.5);
  return value;
}

Vec3 doubled(const Vec3& a, int times) { return {doubled(a.x, times), doubled(a.y, times), doubled(a.z, times)}; }

}  // namespace

real norm(const Vec2& a) { return norm(Vec3{a.x, a.y, real(0)}); }

real norm(const Vec3& a) {
  using std::sqrt;
  const real largest = largest_magnitude(a.x, a.y, a.z);
  if (!kScaleShortVectors || !(largest < real(1))) return sqrt(dot(a, a));
  if (largest == real(0)) return real(0);
  const int times = doublings_to_one(largest);
  const Vec3 scaled = doubled(a, times);
  return halved(sqrt(dot(scaled, scaled)), times);
}

Vec3 normalized(const Vec3& a) {
  using std::sqrt;
  const real largest = largest_magnitude(a.x, a.y, a.z);
  if (largest == real(0)) return a;
  const Vec3 scaled = kScaleShortVectors ? doubled(a, doublings_to_one(largest)) : a;
  const real length = sqrt(dot(scaled, scaled));
  if (length == real(0)) return a;
  return {scaled.x / length, scaled.y / length, scaled.z / length};
}

Mat33 Mat33::identity() {
  Mat33 r;
  for (int i = 0; i < 3; ++i) r.m[i][i] = real(1);
  return r;
}

Mat33 Mat33::transpose() const {
  Mat33 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
  return r;
}

Mat33 operator*(const Mat33& a, const Mat33& b) {
  Mat33 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
  return r;
}

}  // namespace edgetrack
