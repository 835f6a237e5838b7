// SPDX-License-Identifier: BSD-3-Clause
/// The image gradient along a pose's projected edges against their normals.
#include "edgetrack/edge_support.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "real/vector_kernels.h"

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

/// The Sobel gradient of `grey` at row r, column c (inside its border).
__attribute__((always_inline)) inline void sobel_at(const vpImage<unsigned char>& grey, int r, int c, int& gx, int& gy) {
  const unsigned char* above = grey[r - 1];
  const unsigned char* row = grey[r];
  const unsigned char* below = grey[r + 1];
  gx = (above[c + 1] + 2 * row[c + 1] + below[c + 1]) - (above[c - 1] + 2 * row[c - 1] + below[c - 1]);
  gy = (below[c - 1] + 2 * below[c] + below[c + 1]) - (above[c - 1] + 2 * above[c] + above[c + 1]);
}

/// edge_support in floating point from the projected points, a batch of points at a time: where
/// each is read and its gradient's arctangent computed in vector lanes with the one-by-one
/// loop's expressions (the same bits; a lane's operations take no branch, which the compiler
/// could not vectorise), the gradients read and the angles summed one by one in point order (the
/// same sum).
void support_in_lanes(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                      const std::vector<PixelBox>& read_boxes, const ProjectedPoints& projected, const real& floor_squared,
                      const SupportBound& bound, EdgeSupport& support, real& angle_sum) {
  using std::fabs;
  constexpr int kBatch = 32;
  vector_kernels::run([&]() __attribute__((always_inline)) {
    const int height = static_cast<int>(grey.getHeight()), width = static_cast<int>(grey.getWidth());
    const bool within_45 = bound.within_45;
    const real tangent = bound.tangent, least = floor_squared;
    real at_x[kBatch], at_y[kBatch], pixel_x[kBatch], pixel_y[kBatch], normal_x[kBatch], normal_y[kBatch];
    int top[kBatch], left[kBatch], bottom[kBatch], right[kBatch];
    real inside[kBatch], gx[kBatch], gy[kBatch], measured[kBatch], along[kBatch], across[kBatch], folded[kBatch];
    int supported_count = 0, measured_count = 0;
    real sum = angle_sum;
    const size_t count = points.size();
    for (size_t p = 0; p < count;) {
      int n = 0;
      for (; p < count && n < kBatch; ++p) {
        if (!projected.in_front[p]) continue;
        const ControlPoint& point = points[p];
        at_x[n] = projected.pixel[p].x;
        at_y[n] = projected.pixel[p].y;
        pixel_x[n] = point.pixel.x;
        pixel_y[n] = point.pixel.y;
        normal_x[n] = point.normal.x;
        normal_y[n] = point.normal.y;
        const PixelBox& box = read_boxes[p];
        top[n] = box.top;
        left[n] = box.left;
        bottom[n] = box.bottom;
        right[n] = box.right;
        ++n;
      }
      // Where the edge projected with the pose crosses each normal (in place of the point's
      // pixel), and whether that lies one pixel inside the read box (edge_support's loop says why).
      for (int k = 0; k < n; ++k) {
        const real shift = normal_x[k] * (at_x[k] - pixel_x[k]) + normal_y[k] * (at_y[k] - pixel_y[k]);
        const real x = pixel_x[k] + shift * normal_x[k], y = pixel_y[k] + shift * normal_y[k];
        const real t = real(std::max(top[k], 0) + 1), l = real(std::max(left[k], 0) + 1);
        const real b = real(std::min(bottom[k], height) - 2), r = real(std::min(right[k], width) - 2);
        inside[k] = (y >= t) & (y <= b) & (x >= l) & (x <= r) ? real(1) : real(0);
        pixel_x[k] = x;
        pixel_y[k] = y;
      }
      for (int k = 0; k < n; ++k) {
        int sobel_x = 0, sobel_y = 0;
        if (inside[k] != real(0))
          sobel_at(grey, nearest_pixel_of_positive(pixel_y[k]), nearest_pixel_of_positive(pixel_x[k]), sobel_x, sobel_y);
        measured[k] = inside[k] != real(0) && !(real(sobel_x * sobel_x + sobel_y * sobel_y) < least) ? real(1) : real(0);
        gx[k] = real(sobel_x);
        gy[k] = real(sobel_y);
      }
      // angle_of_components' arctangent, of the smaller magnitude over the larger (the one of
      // its two branches it takes; equal magnitudes are the same value either way).
      for (int k = 0; k < n; ++k) {
        along[k] = fabs(gx[k] * normal_x[k] + gy[k] * normal_y[k]);
        across[k] = fabs(gx[k] * normal_y[k] - gy[k] * normal_x[k]);
        folded[k] = arctangent_deg(std::min(across[k], along[k]) / std::max(across[k], along[k]));
      }
      for (int k = 0; k < n; ++k) {
        if (measured[k] == real(0)) continue;
        const real &a = along[k], &c = across[k];
        ++measured_count;
        sum += a == real(0) && c == real(0) ? real(0) : c <= a ? folded[k] : real(90) - folded[k];
        supported_count += within_45 ? c <= tangent * a : a >= tangent * c;
      }
    }
    support.measured += measured_count;
    support.supported += supported_count;
    angle_sum = sum;
  });
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
  if constexpr (std::numeric_limits<real>::is_iec559) {
    if (projected) {
      support_in_lanes(grey, points, read_boxes, *projected, floor_squared, bound, support, angle_sum);
      if (support.measured > 0) support.mean_angle_deg = angle_sum / real(support.measured);
      return support;
    }
  }
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
    int gx = 0, gy = 0;
    sobel_at(grey, r, c, gx, gy);
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
