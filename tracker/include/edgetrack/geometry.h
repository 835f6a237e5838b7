// SPDX-License-Identifier: BSD-3-Clause
/// Small value types for 2D and 3D geometry in `real`: Vec2, Vec3 and the 3x3 matrix Mat33.
#pragma once

#include "real/real.h"

namespace edgetrack {

/// A point or direction in the image plane, in pixels (x to the right, y down).
struct Vec2 {
  real x{0};
  real y{0};
};

FIXED64_SMALL_OPERATION inline Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
FIXED64_SMALL_OPERATION inline Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
FIXED64_SMALL_OPERATION inline Vec2 operator*(const real& s, const Vec2& a) { return {s * a.x, s * a.y}; }
FIXED64_SMALL_OPERATION inline real dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
real norm(const Vec2& a);

/// A point or direction in 3D, in metres when it is a point.
struct Vec3 {
  real x{0};
  real y{0};
  real z{0};
};

FIXED64_SMALL_OPERATION inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
FIXED64_SMALL_OPERATION inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
FIXED64_SMALL_OPERATION inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
FIXED64_SMALL_OPERATION inline Vec3 operator*(const real& s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
FIXED64_SMALL_OPERATION inline real dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
FIXED64_SMALL_OPERATION inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
real norm(const Vec3& a);
/// `a / |a|`; the zero vector stays zero.
Vec3 normalized(const Vec3& a);

/// A 3x3 matrix, row-major: `m[row][col]`.
struct Mat33 {
  real m[3][3] = {{real(0), real(0), real(0)}, {real(0), real(0), real(0)}, {real(0), real(0), real(0)}};

  static Mat33 identity();
  Mat33 transpose() const;
};

Mat33 operator*(const Mat33& a, const Mat33& b);
/// Inline: it runs for every control point in every pose evaluation.
FIXED64_SMALL_OPERATION inline Vec3 operator*(const Mat33& a, const Vec3& v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z, a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}

}  // namespace edgetrack
