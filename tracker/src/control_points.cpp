// SPDX-License-Identifier: BSD-3-Clause
/// Control point sampling along projected edges (equation (1)) and the Edge-ID visibility filter.
#include "edgetrack/control_points.h"

#include <cmath>

namespace edgetrack {

std::vector<ControlPoint> sample_control_points(const EdgeModel& model, const PinholeCamera& camera,
                                                const Se3& camera_from_model, const SamplingParams& params) {
  using std::floor;
  std::vector<ControlPoint> points;
  const real lo_x = real(params.border), hi_x = real(camera.width - 1 - params.border);
  const real lo_y = real(params.border), hi_y = real(camera.height - 1 - params.border);
  for (size_t e = 0; e < model.edges.size(); ++e) {
    Vec3 a = model.vertices[model.edges[e].a], b = model.vertices[model.edges[e].b];
    Vec3 ca = camera_from_model * a, cb = camera_from_model * b;
    real t0, t1;
    if (!clip_to_view(ca, cb, camera, params.clipping, t0, t1)) continue;
    if (t0 > real(0) || t1 < real(1)) {  // keep the part in view
      const Vec3 a0 = a, ca0 = ca;
      if (t0 > real(0)) {
        a = a0 + t0 * (b - a0);
        ca = ca0 + t0 * (cb - ca0);
      }
      if (t1 < real(1)) {
        b = a0 + t1 * (b - a0);
        cb = ca0 + t1 * (cb - ca0);
      }
    }
    const Vec2 pa = camera.project(ca), pb = camera.project(cb);
    const Vec2 d = pb - pa;
    const real length = norm(d);
    const int n = static_cast<int>(floor(length / params.step));  // equation (1)
    if (n <= 0) continue;
    const Vec2 direction{d.x / length, d.y / length};
    const Vec2 normal{-direction.y, direction.x};
    const real wa = real(1) / ca.z, wb = real(1) / cb.z;
    const real half_part = real(1) / (2 * n);
    for (int k = 0; k < n; ++k) {
      const real t = (2 * k + 1) * half_part;  // the centre of part k of n
      const Vec2 pixel = pa + t * d;
      if (pixel.x < lo_x || pixel.x > hi_x || pixel.y < lo_y || pixel.y > hi_y) continue;
      // t runs evenly in the image; 1/Z is affine in t, and the 3D parameter follows from it.
      const real s = t * wb / ((real(1) - t) * wa + t * wb);
      ControlPoint point;
      point.edge = static_cast<int>(e);
      point.point_in_model = a + s * (b - a);
      point.pixel = pixel;
      point.direction = direction;
      point.normal = normal;
      points.push_back(point);
    }
  }
  return points;
}

std::vector<ControlPoint> keep_visible(const std::vector<ControlPoint>& points, const EdgeIdBuffer& edge_ids) {
  std::vector<ControlPoint> visible;
  visible.reserve(points.size());
  for (const ControlPoint& p : points)
    if (edge_ids.shows(p.edge, p.pixel, p.direction)) visible.push_back(p);
  return visible;
}

}  // namespace edgetrack
