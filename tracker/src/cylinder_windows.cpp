// SPDX-License-Identifier: BSD-3-Clause
/// The rim boxes of a cylinder, from the corners of its tessellated side.
#include "edgetrack/cylinder_windows.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/contours.h"

namespace edgetrack {

bool cylinder_rim_boxes(const EdgeModel& model, int cylinder, const PinholeCamera& camera,
                        const Se3& camera_from_model, PixelRect (&boxes)[2]) {
  using std::ceil;
  using std::floor;
  const Cylinder& c = model.cylinders[static_cast<size_t>(cylinder)];
  const Vec3 axis = c.axis_b - c.axis_a;
  const real length2 = dot(axis, axis);
  const Vec3 from_axis = camera_centre_in_model(camera_from_model) - c.axis_a;
  const real along = dot(from_axis, axis);
  const Vec3 across = from_axis - (along / length2) * axis;
  if (!(dot(across, across) > c.radius * c.radius)) return false;

  const real near = real(0.02), margin = real(32);
  const real lo_x = -margin, hi_x = real(camera.width - 1) + margin;
  const real lo_y = -margin, hi_y = real(camera.height - 1) + margin;
  real min_x[2] = {hi_x, hi_x}, min_y[2] = {hi_y, hi_y}, max_x[2] = {lo_x, lo_x}, max_y[2] = {lo_y, lo_y};
  // Each corner of the cylinder's facets once: its rims' points (EdgeModel::cylinder_points).
  const size_t rim_points = 2 * (kCylinderSides + 1), first = static_cast<size_t>(cylinder) * rim_points;
  for (size_t i = first; i < first + rim_points; ++i) {
    const Vec3& corner = model.cylinder_points[i];
    const Vec3 in_camera = camera_from_model * corner;
    if (!(in_camera.z > near)) return false;
    const Vec2 p = camera.project(in_camera);
    if (p.x < lo_x || p.x > hi_x || p.y < lo_y || p.y > hi_y) return false;
    const int end = real(2) * dot(corner - c.axis_a, axis) > length2 ? 1 : 0;
    min_x[end] = std::min(min_x[end], p.x);
    max_x[end] = std::max(max_x[end], p.x);
    min_y[end] = std::min(min_y[end], p.y);
    max_y[end] = std::max(max_y[end], p.y);
  }
  for (int end = 0; end < 2; ++end) {
    boxes[end].x0 = std::max(0, static_cast<int>(floor(min_x[end])) - 1);
    boxes[end].y0 = std::max(0, static_cast<int>(floor(min_y[end])) - 1);
    boxes[end].x1 = std::min(camera.width - 1, static_cast<int>(ceil(max_x[end])) + 1);
    boxes[end].y1 = std::min(camera.height - 1, static_cast<int>(ceil(max_y[end])) + 1);
  }
  return true;
}

}  // namespace edgetrack
