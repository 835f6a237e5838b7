// SPDX-License-Identifier: BSD-3-Clause
/// The pose's first-order covariance propagated to the model's image displacement.
#include "edgetrack/pose_uncertainty.h"

#include <cmath>

namespace edgetrack {
namespace {

constexpr int kDof = 6;

/// The pose perturbation the covariance is over: a translation v (mm) and a turn w about the
/// model's centre, scaled by the model's radius (mm at its farthest vertex), so that every
/// column of the Jacobian is pixels per millimetre of some point's motion: balanced columns keep
/// the fixed-point Cholesky well within range.
struct Perturbation {
  Vec3 centre;          ///< model frame, metres
  real radius_mm{1};
};

template <typename Visit>
void for_each_overlay_point(const EdgeModel& model, Visit visit) {
  for (const Vec3& v : model.vertices) visit(v);
  for (const Cylinder& c : model.cylinders) {
    visit(c.axis_a);
    visit(c.axis_b);
  }
  for (const Circle& c : model.circles) visit(c.centre);
}

Perturbation perturbation_of(const EdgeModel& model) {
  Perturbation p;
  Vec3 sum;
  int count = 0;
  for_each_overlay_point(model, [&](const Vec3& v) {
    sum = sum + v;
    ++count;
  });
  if (count == 0) return p;
  p.centre = (real(1) / real(count)) * sum;
  real farthest(0);
  for_each_overlay_point(model, [&](const Vec3& v) {
    const real r = real(1000) * norm(v - p.centre);
    if (r > farthest) farthest = r;
  });
  if (farthest > real(0)) p.radius_mm = farthest;
  return p;
}

/// d(n . pixel)/d(v, w) for the camera-frame point `in_camera_mm`, `offset_mm` = R (p - centre).
void pixel_gradient(const PinholeCamera& camera, const Vec3& in_camera_mm, const Vec3& offset_mm,
                    const Perturbation& perturbation, const Vec2& n, real g[kDof]) {
  const real inv_z = real(1) / in_camera_mm.z;
  const real nu = n.x * camera.px * inv_z;
  const real nv = n.y * camera.py * inv_z;
  const Vec3 a{nu, nv, -(nu * (in_camera_mm.x * inv_z) + nv * (in_camera_mm.y * inv_z))};
  // d(point)/dw = -hat(offset) / radius, so a . d(point)/dw = -(a x offset) / radius.
  const Vec3 turn = (-real(1) / perturbation.radius_mm) * cross(a, offset_mm);
  g[0] = a.x;
  g[1] = a.y;
  g[2] = a.z;
  g[3] = turn.x;
  g[4] = turn.y;
  g[5] = turn.z;
}

/// In-place Cholesky A = L L^T of the lower triangle; false when a pivot is not clearly positive
/// (a direction the matches do not see).
bool cholesky(real a[kDof][kDof]) {
  using std::sqrt;
  real largest(0);
  for (int k = 0; k < kDof; ++k)
    if (a[k][k] > largest) largest = a[k][k];
  const real least = real(1e-6) * largest;
  if (!(largest > real(0))) return false;
  for (int k = 0; k < kDof; ++k) {
    real pivot = a[k][k];
    for (int j = 0; j < k; ++j) pivot -= a[k][j] * a[k][j];
    if (!(pivot > least)) return false;
    a[k][k] = sqrt(pivot);
    const real inv = real(1) / a[k][k];
    for (int i = k + 1; i < kDof; ++i) {
      real s = a[i][k];
      for (int j = 0; j < k; ++j) s -= a[i][j] * a[k][j];
      a[i][k] = s * inv;
    }
  }
  return true;
}

/// |L^-1 g|^2, or a negative value when a component passes `cap` (the variance is then off scale).
real whitened_square(const real l[kDof][kDof], const real g[kDof], const real& cap) {
  using std::fabs;
  real z[kDof];
  real sum(0);
  for (int k = 0; k < kDof; ++k) {
    real s = g[k];
    for (int j = 0; j < k; ++j) s -= l[k][j] * z[j];
    z[k] = s / l[k][k];
    if (fabs(z[k]) > cap) return real(-1);
    sum += z[k] * z[k];
  }
  return sum;
}

}  // namespace

real pose_uncertainty_px(const std::vector<EdgeMatch>& matches, const EdgeModel& model, const PinholeCamera& camera,
                         const Se3& pose, const real& sigma, const real& tukey_c, const real& tukey_floor) {
  using std::fabs;
  using std::sqrt;
  const real unconstrained = real(kUnconstrainedPx);
  const Perturbation perturbation = perturbation_of(model);
  real cut = tukey_c * sigma;
  if (cut < tukey_floor) cut = tukey_floor;
  real information[kDof][kDof] = {};
  real g[kDof];
  for (const EdgeMatch& match : matches) {
    if (match.outlier) continue;
    const Vec3 in_camera = pose * match.point.point_in_model;
    if (in_camera.z <= real(0)) continue;
    const real distance = fabs(dot(match.point.normal, camera.project(in_camera) - match.used()));
    if (distance >= cut) continue;
    const real u = distance / cut;
    const real weight = (real(1) - u * u) * (real(1) - u * u);
    const Vec3 offset = real(1000) * (pose.rotation() * (match.point.point_in_model - perturbation.centre));
    pixel_gradient(camera, real(1000) * in_camera, offset, perturbation, match.point.normal, g);
    for (int i = 0; i < kDof; ++i) {
      const real wg = weight * g[i];
      for (int j = 0; j <= i; ++j) information[i][j] += wg * g[j];
    }
  }
  if (!cholesky(information)) return unconstrained;
  // A whitened component beyond this is a direction no match sees; it also keeps the squares
  // within S40.23's range.
  const real cap = real(1e4);
  real worst(0);
  bool off_scale = false;
  for_each_overlay_point(model, [&](const Vec3& v) {
    const Vec3 in_camera = pose * v;
    if (off_scale || in_camera.z <= real(0)) return;
    const Vec3 offset = real(1000) * (pose.rotation() * (v - perturbation.centre));
    pixel_gradient(camera, real(1000) * in_camera, offset, perturbation, Vec2{real(1), real(0)}, g);
    const real along_u = whitened_square(information, g, cap);
    pixel_gradient(camera, real(1000) * in_camera, offset, perturbation, Vec2{real(0), real(1)}, g);
    const real along_v = whitened_square(information, g, cap);
    if (along_u < real(0) || along_v < real(0)) {
      off_scale = true;
      return;
    }
    const real deviation = sigma * sqrt(along_u + along_v);
    if (deviation > worst) worst = deviation;
  });
  if (off_scale || worst > unconstrained) return unconstrained;
  return worst;
}

}  // namespace edgetrack
