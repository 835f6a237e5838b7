// SPDX-License-Identifier: BSD-3-Clause
/// Cylinder silhouette generators and circle polygons for the current pose.
#include "edgetrack/contours.h"

#include <cmath>

namespace edgetrack {

Vec3 camera_centre_in_model(const Se3& camera_from_model) {
  return -(camera_from_model.rotation().transpose() * camera_from_model.translation());
}

bool cylinder_generators(const Cylinder& cylinder, const Vec3& camera_centre, Vec3 (&lines)[2][2]) {
  using std::sqrt;
  const Vec3 axis = cylinder.axis_b - cylinder.axis_a;
  const Vec3 d = normalized(axis);
  const Vec3 to_camera = camera_centre - cylinder.axis_a;
  const Vec3 across = to_camera - dot(to_camera, d) * d;
  const real distance = norm(across);
  if (!(distance > cylinder.radius)) return false;
  // Unit vectors and the ratio r / D keep every product near 1, for every `real`.
  const Vec3 w = (real(1) / distance) * across;
  const Vec3 side = cross(d, w);
  const real ratio = cylinder.radius / distance;
  const real along = sqrt(real(1) - ratio * ratio);
  for (int k = 0; k < 2; ++k) {
    const Vec3 radial = ratio * w + (k == 0 ? along : -along) * side;
    const Vec3 offset = cylinder.radius * radial;
    lines[k][0] = cylinder.axis_a + offset;
    lines[k][1] = cylinder.axis_b + offset;
  }
  return true;
}

bool cap_rim_clear_of_side(const Cylinder& cylinder, const Vec3& cap_centre, const Vec3& rim_point,
                           const Vec3& camera_centre) {
  const Vec3 to_camera = camera_centre - cap_centre;
  const Vec3 other_end = norm(cap_centre - cylinder.axis_a) < norm(cap_centre - cylinder.axis_b) ? cylinder.axis_b
                                                                                                  : cylinder.axis_a;
  if (dot(cap_centre - other_end, to_camera) > real(0)) return true;  // the cap faces the camera
  const Vec3 outward = (real(1) / cylinder.radius) * (rim_point - cap_centre);
  return dot(outward, to_camera) > cylinder.radius;
}

void curved_contours(const EdgeModel& model, const Se3& camera_from_model, std::vector<ContourSegment>& out) {
  out.clear();
  const Vec3 centre = camera_centre_in_model(camera_from_model);
  for (size_t c = 0; c < model.cylinders.size(); ++c) {
    Vec3 lines[2][2];
    if (!cylinder_generators(model.cylinders[c], centre, lines)) continue;
    for (int k = 0; k < 2; ++k)
      out.push_back({lines[k][0], lines[k][1], cylinder_primitive(model, static_cast<int>(c), k)});
  }
  for (size_t k = 0; k < model.circles.size(); ++k) {
    const std::vector<Vec3>& rim = model.circles[k].rim;
    const int primitive = circle_primitive(model, static_cast<int>(k));
    for (size_t s = 0; s + 1 < rim.size(); ++s) out.push_back({rim[s], rim[s + 1], primitive});
  }
}

}  // namespace edgetrack
