// SPDX-License-Identifier: BSD-3-Clause
/// Se3 on top of ports/vnl's rotation helpers (Rodrigues, thetaU and the exp-map coefficients).
#include "edgetrack/se3.h"

#include <cstring>
#include <type_traits>

#include "vnl/vnl_rotation_matrix.h"

namespace edgetrack {
namespace {

vnl_vector_fixed<real, 3> to_vnl(const Vec3& v) { return vnl_vector_fixed<real, 3>(v.x, v.y, v.z); }

Mat33 from_vnl(const vnl_matrix_fixed<real, 3, 3>& m) {
  Mat33 r;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) r.m[i][j] = m(i, j);
  return r;
}

vnl_matrix_fixed<real, 3, 3> to_vnl(const Mat33& m) {
  vnl_matrix_fixed<real, 3, 3> r;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) r(i, j) = m.m[i][j];
  return r;
}

/// Solves m * x = b by Cramer's rule; m is V(w), well conditioned for |w| < 2 pi.
Vec3 solve(const Mat33& m, const Vec3& b) {
  const Vec3 c0{m.m[0][0], m.m[1][0], m.m[2][0]};
  const Vec3 c1{m.m[0][1], m.m[1][1], m.m[2][1]};
  const Vec3 c2{m.m[0][2], m.m[1][2], m.m[2][2]};
  const real det = dot(c0, cross(c1, c2));
  return {dot(b, cross(c1, c2)) / det, dot(c0, cross(b, c2)) / det, dot(c0, cross(c1, b)) / det};
}

}  // namespace

Mat33 so3_left_jacobian(const Vec3& w) {
  const vnl_rotation_coefficients<real> k = vnl_rotation_exp_coefficients(to_vnl(w));
  const Mat33 h = hat(w);
  const Mat33 h2 = h * h;
  Mat33 v = Mat33::identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v.m[i][j] = v.m[i][j] + k.b * h.m[i][j] + k.c * h2.m[i][j];
  return v;
}

Mat33 hat(const Vec3& w) { return from_vnl(vnl_rotation_hat(to_vnl(w))); }

Vec3 vee(const Mat33& m) {
  const vnl_vector_fixed<real, 3> w = vnl_rotation_vee(to_vnl(m));
  return {w[0], w[1], w[2]};
}

Mat33 rotation_exp(const Vec3& w) { return from_vnl(vnl_rotation_matrix(to_vnl(w))); }

Vec3 rotation_log(const Mat33& rotation) {
  const vnl_vector_fixed<real, 3> w = vnl_rotation_thetau(to_vnl(rotation));
  return {w[0], w[1], w[2]};
}

Se3 Se3::exp(const Twist& twist) { return Se3(rotation_exp(twist.w), so3_left_jacobian(twist.w) * twist.v); }

Se3 Se3::from_theta_u(const Vec3& translation, const Vec3& theta_u) { return Se3(rotation_exp(theta_u), translation); }

Twist Se3::log() const {
  Twist t;
  t.w = rotation_log(rotation_);
  t.v = solve(so3_left_jacobian(t.w), translation_);
  return t;
}

Se3 Se3::inverse() const {
  const Mat33 rt = rotation_.transpose();
  return Se3(rt, -(rt * translation_));
}

Se3 Se3::operator*(const Se3& rhs) const {
  return Se3(rotation_ * rhs.rotation_, rotation_ * rhs.translation_ + translation_);
}

bool same_bits(const Se3& a, const Se3& b) {
  static_assert(std::is_trivially_copyable<Se3>::value && sizeof(Se3) == 12 * sizeof(real), "Se3 is 12 reals");
  return std::memcmp(&a, &b, sizeof(Se3)) == 0;
}

}  // namespace edgetrack
