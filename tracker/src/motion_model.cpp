// SPDX-License-Identifier: BSD-3-Clause
/// The damped constant-velocity prediction and the search range that follows it.
#include "edgetrack/motion_model.h"

namespace edgetrack {
namespace {

/// Only vertices at least this far in front of the camera are compared (metres).
const real kNear = real(0.01);

Twist scaled(const Twist& t, const real& s) { return {s * t.v, s * t.w}; }

}  // namespace

real largest_image_shift(const EdgeModel& model, const PinholeCamera& camera, const Se3& a, const Se3& b) {
  real worst(0);
  for (const Vec3& vertex : model.vertices) {
    const Vec3 pa = a * vertex, pb = b * vertex;
    if (pa.z < kNear || pb.z < kNear) continue;
    const real shift = norm(camera.project(pb) - camera.project(pa));
    if (shift > worst) worst = shift;
  }
  return worst;
}

void MotionModel::trust(const Se3& camera_from_model, const EdgeModel& model, const PinholeCamera& camera,
                        unsigned range) {
  // The mean motion per frame since the last trusted pose; the start pose is no frame's.
  if (moving_) velocity_ = scaled((camera_from_model * trusted_.inverse()).log(), real(1) / real(frames_since_trusted_));
  moving_ = true;
  trusted_ = camera_from_model;
  frames_since_trusted_ = 1;
  const Se3 ahead = Se3::exp(velocity_) * trusted_;
  motion_px_ = largest_image_shift(model, camera, trusted_, ahead);
  speed_px_ = motion_px_;
  const real searched = real(static_cast<int>(range));
  real share = (motion_px_ - searched) / searched;
  share = share < real(0) ? real(0) : share > real(1) ? real(1) : share;
  share = share * params_.velocity_share;
  prediction_ = Se3::exp(scaled(velocity_, share)) * trusted_;
  next_share_ = share * params_.lost_damping;
  if (wide_left_ > 0) --wide_left_;
}

void MotionModel::lose(const EdgeModel& model, const PinholeCamera& camera) {
  ++frames_since_trusted_;
  const Se3 from = prediction_;
  prediction_ = Se3::exp(scaled(velocity_, next_share_)) * prediction_;
  motion_px_ = largest_image_shift(model, camera, from, prediction_);
  next_share_ = next_share_ * params_.lost_damping;
  if (wide_left_ < params_.recovery_frames) wide_left_ = params_.recovery_frames;
}

void MotionModel::reset(const Se3& camera_from_model) {
  trusted_ = camera_from_model;
  prediction_ = camera_from_model;
  velocity_ = Twist{};
  next_share_ = real(0);
  motion_px_ = real(0);
  speed_px_ = real(0);
  moving_ = false;
  frames_since_trusted_ = 1;
  wide_left_ = params_.start_frames;
}

unsigned MotionModel::search_range(unsigned range) const {
  return widened(range, params_.range_per_motion * (motion_px_ - real(static_cast<int>(range))));
}

unsigned MotionModel::retry_range(unsigned range) const { return widened(range, speed_px_); }

unsigned MotionModel::widened(unsigned range, const real& beyond) const {
  const int base = static_cast<int>(range) * (wide_left_ > 0 ? 2 : 1);
  int grow = beyond > real(0) ? static_cast<int>(beyond) : 0;
  if (real(grow) < beyond) ++grow;  // rounded up
  const int most = params_.max_range_factor * static_cast<int>(range);
  const int searched = base + grow;
  return static_cast<unsigned>(searched < most ? searched : most);
}

}  // namespace edgetrack
