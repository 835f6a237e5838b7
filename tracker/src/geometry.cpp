// SPDX-License-Identifier: BSD-3-Clause
/// Norms and matrix products for the geometry value types.
#include "edgetrack/geometry.h"

#include <cmath>

namespace edgetrack {

real norm(const Vec2& a) {
  using std::sqrt;
  return sqrt(dot(a, a));
}

real norm(const Vec3& a) {
  using std::sqrt;
  return sqrt(dot(a, a));
}

Vec3 normalized(const Vec3& a) {
  const real length = norm(a);
  if (length == real(0)) return a;
  return {a.x / length, a.y / length, a.z / length};
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

Vec3 operator*(const Mat33& a, const Vec3& v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z, a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}

}  // namespace edgetrack
