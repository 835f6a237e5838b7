// SPDX-License-Identifier: BSD-3-Clause
/// The image gradient along a pose's projected edges against their normals.
#include "edgetrack/edge_support.h"

#include <algorithm>
#include <cmath>

namespace edgetrack {
namespace {

/// atan(t) in degrees for t in [0, 1]: 45 t + t (1 - t) (14.02 + 3.80 t), within 0.09 degree
/// (the radian form (pi/4) t + t (1 - t) (0.2447 + 0.0663 t) is a known minimax fit).
real arctangent_deg(const real& t) {
  return real(45) * t + t * (real(1) - t) * (real(14.02) + real(3.80) * t);
}

/// The pixel nearest to coordinate x >= 0: floor(x + 1/2), which for a positive number is the
/// truncation a conversion to int makes (no floor: without SSE4.1 a host's floor is a dozen
/// instructions).
int nearest_pixel_of_positive(const real& x) { return static_cast<int>(x + real(0.5)); }

/// The angle atan(across / along) in degrees, [0, 90], of a gradient's magnitudes along and
/// across a normal.
real angle_of_components(const real& along, const real& across) {
  if (along == real(0) && across == real(0)) return real(0);
  if (across <= along) return arctangent_deg(across / along);
  return real(90) - arctangent_deg(along / across);
}

}  // namespace

real gradient_normal_angle_deg(const real& gx, const real& gy, const Vec2& normal) {
  using std::fabs;
  return angle_of_components(fabs(gx * normal.x + gy * normal.y), fabs(gx * normal.y - gy * normal.x));
}

SupportBound support_bound(const real& support_angle_deg) {
  // Bisection on [0, 1], where the polynomial rises monotonically: arctangent_deg(tangent) is
  // at most the angle, so across <= tangent along gives arctangent_deg(across / along)'s verdict.
  SupportBound bound;
  bound.within_45 = support_angle_deg <= real(45);
  const real angle = bound.within_45 ? support_angle_deg : real(90) - support_angle_deg;
  real low(0), high(1);
  for (int step = 0; step < 48; ++step) {
    const real middle = (low + high) * real(0.5);
    if (arctangent_deg(middle) <= angle) low = middle;
    else high = middle;
  }
  bound.tangent = low;
  return bound;
}

EdgeSupport edge_support(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                         const std::vector<PixelBox>& read_boxes, const PinholeCamera& camera, const Se3& pose,
                         const real& gradient_floor, const SupportBound& bound, const ProjectedPoints* projected) {
  using std::fabs;
  EdgeSupport support;
  support.visible = static_cast<int>(points.size());
  const int height = static_cast<int>(grey.getHeight()), width = static_cast<int>(grey.getWidth());
  const real floor_squared = gradient_floor * gradient_floor;
  real angle_sum(0);
  for (size_t p = 0; p < points.size(); ++p) {
    const ControlPoint& point = points[p];
    // Where the edge projected with `pose` crosses the point's normal: the point's search path,
    // whose pixels the grey image holds (a move along the edge would leave them).
    Vec2 at;
    if (projected) {
      if (!projected->in_front[p]) continue;
      at = projected->pixel[p];
    } else {
      const Vec3 in_camera = pose * point.point_in_model;
      if (in_camera.z <= real(0)) continue;
      at = camera.project(in_camera);
    }
    const real shift = dot(point.normal, at - point.pixel);
    const Vec2 pixel = point.pixel + shift * point.normal;
    // Read only where this frame's grey image is up to date for the point, one pixel inside
    // for the Sobel's 3x3 neighbourhood.
    const PixelBox& box = read_boxes[p];
    const real top = real(std::max(box.top, 0) + 1), left = real(std::max(box.left, 0) + 1);
    const real bottom = real(std::min(box.bottom, height) - 2), right = real(std::min(box.right, width) - 2);
    if (!(pixel.y >= top && pixel.y <= bottom && pixel.x >= left && pixel.x <= right)) continue;
    const int r = nearest_pixel_of_positive(pixel.y), c = nearest_pixel_of_positive(pixel.x);  // pixel >= 1 here
    const unsigned char* above = grey[r - 1];
    const unsigned char* row = grey[r];
    const unsigned char* below = grey[r + 1];
    const int gx = (above[c + 1] + 2 * row[c + 1] + below[c + 1]) - (above[c - 1] + 2 * row[c - 1] + below[c - 1]);
    const int gy = (below[c - 1] + 2 * below[c] + below[c + 1]) - (above[c - 1] + 2 * above[c] + above[c + 1]);
    if (real(gx * gx + gy * gy) < floor_squared) continue;
    const real along = fabs(real(gx) * point.normal.x + real(gy) * point.normal.y);
    const real across = fabs(real(gx) * point.normal.y - real(gy) * point.normal.x);
    ++support.measured;
    angle_sum += angle_of_components(along, across);
    if (bound.within_45 ? across <= bound.tangent * along : along >= bound.tangent * across) ++support.supported;
  }
  if (support.measured > 0) support.mean_angle_deg = angle_sum / real(support.measured);
  return support;
}

}  // namespace edgetrack
