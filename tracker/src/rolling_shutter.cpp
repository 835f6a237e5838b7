// SPDX-License-Identifier: BSD-3-Clause
/// Control points at their rows' read times under a constant velocity.
#include "edgetrack/rolling_shutter.h"

#include <cmath>

#include "edgetrack/tracker_memory.h"

namespace edgetrack {
namespace {

/// exp(t velocity) y - y for a camera-frame point y, to second order in t: with
/// a = w x y + v, t a + t^2 / 2 w x a. A frame's rotation is a few hundredths of a radian, so
/// the third-order term stays under a micrometre at the half frame a row is at most away.
Vec3 motion_over(const Twist& velocity, const Vec3& y, const real& t) {
  const Vec3 a = cross(velocity.w, y) + velocity.v;
  return t * a + (real(0.5) * t * t) * cross(velocity.w, a);
}

/// Pixels per frame: where the image of y moves at `velocity`, by a difference over a short
/// time (a sixteenth of a frame, under a pixel at the motion where a rolling shutter matters).
Vec2 image_flow(const PinholeCamera& camera, const Twist& velocity, const Vec3& y, const Vec2& at) {
  const real h(0.0625);
  const Vec3 ahead = y + motion_over(velocity, y, h);
  if (!(ahead.z > real(0))) return {real(0), real(0)};
  return real(16) * (camera.project(ahead) - at);
}

}  // namespace

bool is_zero(const Twist& twist) {
  const real zero(0);
  return twist.v.x == zero && twist.v.y == zero && twist.v.z == zero && twist.w.x == zero && twist.w.y == zero &&
         twist.w.z == zero;
}

void move_to_row_times(std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& pose,
                       const Twist& velocity, const real& readout) {
  if (readout == real(0) || camera.height <= 0 || is_zero(velocity)) return;
  using std::sqrt;
  const real per_row = readout / real(camera.height);
  const Mat33 back = pose.rotation().transpose();
  for (ControlPoint& p : points) {
    const Vec3 y = pose * p.point_in_model;
    Vec3 moved = y;
    Vec2 pixel = p.pixel;
    // The row's time from the sampled row, then from the row the motion moved the point to.
    for (int pass = 0; pass < 2; ++pass) {
      moved = y + motion_over(velocity, y, row_time(pixel.y, per_row, camera.height));
      if (!(moved.z > real(0))) break;
      pixel = camera.project(moved);
    }
    if (!(moved.z > real(0))) continue;
    // The edge's image is sheared: along it, each row down is per_row frames later, so the
    // direction d gains flow * per_row * d.y (the flow's own change along the edge is left out).
    const Vec2 flow = image_flow(camera, velocity, moved, pixel);
    const Vec2 sheared = p.direction + (per_row * p.direction.y) * flow;
    const real length = sqrt(dot(sheared, sheared));
    if (!(length > real(0))) continue;
    p.point_in_model = p.point_in_model + back * (moved - y);
    p.pixel = pixel;
    p.direction = (real(1) / length) * sheared;
    p.normal = Vec2{-p.direction.y, p.direction.x};
  }
}

void RowTimes::move(std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& pose,
                    const Twist& velocity, const real& readout) {
  if (readout == real(0) || is_zero(velocity)) {
    sampled_.clear();  // a global shutter copies nothing, and again() finds no earlier frame's points
    return;
  }
  sampled_ = points;
  move_to_row_times(points, camera, pose, velocity, readout);
}

bool RowTimes::again(std::vector<ControlPoint>& points, std::vector<EdgeMatch>& matches, const PinholeCamera& camera,
                     const Se3& pose, const Twist& velocity, const real& readout) {
  // The matches may be a caller's: each index is checked before any is read.
  const size_t count = sampled_.size();
  if (points.size() != count) return false;
  for (const EdgeMatch& m : matches)
    if (m.point_index < 0 || static_cast<size_t>(m.point_index) >= count) return false;
  moved_ = sampled_;
  move_to_row_times(moved_, camera, pose, velocity, readout);
  for (EdgeMatch& m : matches) m.point.point_in_model = moved_[static_cast<size_t>(m.point_index)].point_in_model;
  for (size_t k = 0; k < count; ++k) points[k].point_in_model = moved_[k].point_in_model;
  return true;
}

size_t RowTimes::heap_bytes() const { return capacity_bytes(sampled_) + capacity_bytes(moved_); }

void RowTimes::reserve(size_t points) {
  sampled_.reserve(points);
  moved_.reserve(points);
}

}  // namespace edgetrack
