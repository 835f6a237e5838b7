// SPDX-License-Identifier: BSD-3-Clause
/// Rigid transforms. `b_from_a * point_in_a` gives the point in frame b; the tracker's state is
/// `camera_from_model`. Invariant: rotation() is orthonormal to within a few units of `real`'s
/// resolution, as produced by exp() or from_theta_u().
#pragma once

#include "edgetrack/geometry.h"

namespace edgetrack {

/// A tangent vector of SE(3): v (translation part, metres) and w (rotation vector, radians).
struct Twist {
  Vec3 v;
  Vec3 w;
};

/// The cross-product matrix: hat(w) * p == cross(w, p).
Mat33 hat(const Vec3& w);
/// The inverse of hat on the antisymmetric part of m.
Vec3 vee(const Mat33& m);
/// Rodrigues' formula: the rotation exp(hat(w)).
Mat33 rotation_exp(const Vec3& w);
/// The left Jacobian of SO(3), J(w) = I + b hat(w) + c hat(w)^2: the map from v to the
/// translation in Se3::exp, and d(exp(hat(w)) y)/dw = -hat(exp(hat(w)) y) J(w) for the pose step.
Mat33 so3_left_jacobian(const Vec3& w);
/// The rotation vector theta * u, theta in [0, pi], of a rotation matrix (its logarithm).
Vec3 rotation_log(const Mat33& rotation);

class Se3 {
 public:
  Se3() : rotation_(Mat33::identity()) {}
  Se3(const Mat33& rotation, const Vec3& translation) : rotation_(rotation), translation_(translation) {}

  /// The group exponential: rotation exp(hat(w)), translation V(w) * v.
  static Se3 exp(const Twist& twist);
  /// ViSP's pose vector: translation (metres) and thetaU (radians), as in a .pos file.
  static Se3 from_theta_u(const Vec3& translation, const Vec3& theta_u);

  /// The local step both pose solvers take around a start pose: rotation exp(hat(w)) R,
  /// translation t + v (metres), so that a zero step is *this and the step's translation is
  /// the camera-frame one, unrotated.
  Se3 retract(const Vec3& v, const Vec3& w) const { return Se3(rotation_exp(w) * rotation_, translation_ + v); }
  /// The inverse of exp: exp(log()) == *this.
  Twist log() const;
  Vec3 theta_u() const { return rotation_log(rotation_); }
  Se3 inverse() const;
  Se3 operator*(const Se3& rhs) const;
  Vec3 operator*(const Vec3& point) const { return rotation_ * point + translation_; }

  const Mat33& rotation() const { return rotation_; }
  const Vec3& translation() const { return translation_; }

 private:
  Mat33 rotation_;
  Vec3 translation_;
};

/// Whether two poses hold the same numbers bit for bit (signed zeros told apart).
bool same_bits(const Se3& a, const Se3& b);

}  // namespace edgetrack
