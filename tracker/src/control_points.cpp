// SPDX-License-Identifier: BSD-3-Clause
/// Control point sampling along projected edges (equation (1)) and the Edge-ID visibility filter.
#include "edgetrack/control_points.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/contours.h"
#include "real/divisor.h"

namespace edgetrack {
namespace {

ControlPoint make_point(int primitive, const Vec3& point_in_model, const Vec2& pixel, const Vec2& direction) {
  ControlPoint point;
  point.edge = primitive;
  point.point_in_model = point_in_model;
  point.pixel = pixel;
  point.direction = direction;
  point.normal = Vec2{-direction.y, direction.x};
  return point;
}

/// Where the sampled points go: kept up to a maximum (0: none), the ones past it counted.
class PointSink {
 public:
  PointSink(std::vector<ControlPoint>& points, size_t max_points) : points_(points), max_points_(max_points) {}
  void push_back(const ControlPoint& point) {
    if (max_points_ == 0 || points_.size() < max_points_) points_.push_back(point);
    else ++left_out_;
  }
  size_t left_out() const { return left_out_; }

 private:
  std::vector<ControlPoint>& points_;
  size_t max_points_;
  size_t left_out_ = 0;
};

/// The image window control points must fall in.
struct Window {
  real lo_x, hi_x, lo_y, hi_y;
  bool contains(const Vec2& p) const { return p.x >= lo_x && p.x <= hi_x && p.y >= lo_y && p.y <= hi_y; }
};

/// Pieces of a projected segment's polyline through a lens, for its length and its points'
/// parameters: as many as keep the curve within 0.02 px of them (a piece then errs on its length
/// by under 1e-3 px; the points themselves lie on the curve), at most kCurvePieces.
constexpr int kCurvePieces = 64;

/// Equation (1) along the image of segment a-b through the lens, a curve: n = floor(curve
/// length / step) points at the centres of n equal lengths of it, each the image of its 3D
/// point (on the curve, not on a chord), with the curve's own direction there. The pinhole
/// image of the segment is a straight line in normalised coordinates; t runs evenly along it,
/// and the lens moves each of its points.
void sample_curve(const Vec3& a, const Vec3& b, const Vec3& ca, const Vec3& cb, int primitive,
                  const PinholeCamera& camera, const SamplingParams& params, const Window& window,
                  PointSink& points) {
  using std::floor;
  // Each end's depth divides three values (bit for bit the divisions themselves).
  const Divisor<real> by_za(ca.z), by_zb(cb.z);
  const Vec2 na{by_za.divide(ca.x), by_za.divide(ca.y)}, nb{by_zb.divide(cb.x), by_zb.divide(cb.y)};
  const Vec2 chord = nb - na;
  const int pieces = camera.chord_pieces(na, nb, real(0.02), kCurvePieces);
  // Lengths in pixels along the polyline of the curve.
  const auto pixel_length = [&camera](const Vec2& d) { return norm(Vec2{camera.px * d.x, camera.py * d.y}); };
  // Divisions are costly on the target: each quotient the loops repeat is taken once here.
  const real per_piece = real(1) / real(pieces);
  real lengths[kCurvePieces + 1];
  lengths[0] = real(0);
  Vec2 previous = camera.distort(na);
  for (int k = 1; k <= pieces; ++k) {
    const Vec2 next = camera.distort(k == pieces ? nb : na + (real(k) * per_piece) * chord);
    lengths[k] = lengths[k - 1] + pixel_length(next - previous);
    previous = next;
  }
  const real length = lengths[pieces];
  const int n = static_cast<int>(floor(length / params.step));  // equation (1)
  if (n <= 0) return;
  const real wa = by_za.divide(real(1)), wb = by_zb.divide(real(1));
  const real spacing = length / real(n);
  int piece = 0;
  for (int k = 0; k < n; ++k) {
    const real target = (real(k) + real(0.5)) * spacing;  // the centre of part k of n
    while (piece + 1 < pieces && lengths[piece + 1] < target) ++piece;
    const real span = lengths[piece + 1] - lengths[piece];
    const real within = span > real(0) ? (target - lengths[piece]) / span : real(0);
    const real t = (real(piece) + within) * per_piece;
    LensJacobian j;
    const Vec2 pixel = camera.to_pixel(camera.distort(na + t * chord, j));
    if (!window.contains(pixel)) continue;
    // The curve's direction: the lens's derivative applied to the line's, in pixels.
    const Vec2 along{camera.px * (j.xx * chord.x + j.xy * chord.y), camera.py * (j.yx * chord.x + j.yy * chord.y)};
    const real along_length = norm(along);
    if (!(along_length > real(0))) continue;
    const real s = t * wb / ((real(1) - t) * wa + t * wb);
    const real unit = real(1) / along_length;
    points.push_back(make_point(primitive, a + s * (b - a), pixel, Vec2{along.x * unit, along.y * unit}));
  }
}

/// Equation (1) on the part in view of the 3D segment a-b (model frame) of primitive `primitive`.
void sample_segment(Vec3 a, Vec3 b, int primitive, const PinholeCamera& camera, const Se3& camera_from_model,
                    const SamplingParams& params, const Window& window, PointSink& points) {
  using std::floor;
  Vec3 ca = camera_from_model * a, cb = camera_from_model * b;
  real t0, t1;
  if (!clip_to_view(ca, cb, camera, params.clipping, t0, t1)) return;
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
  if (camera.distorted()) {
    sample_curve(a, b, ca, cb, primitive, camera, params, window, points);
    return;
  }
  const Vec2 pa = camera.project(ca), pb = camera.project(cb);
  const Vec2 d = pb - pa;
  const real length = norm(d);
  const int n = static_cast<int>(floor(length / params.step));  // equation (1)
  if (n <= 0) return;
  const Vec2 direction{d.x / length, d.y / length};
  const real wa = real(1) / ca.z, wb = real(1) / cb.z;
  const real half_part = real(1) / (2 * n);
  for (int k = 0; k < n; ++k) {
    const real t = (2 * k + 1) * half_part;  // the centre of part k of n
    const Vec2 pixel = pa + t * d;
    if (!window.contains(pixel)) continue;
    // t runs evenly in the image; 1/Z is affine in t, and the 3D parameter follows from it.
    const real s = t * wb / ((real(1) - t) * wa + t * wb);
    points.push_back(make_point(primitive, a + s * (b - a), pixel, direction));
  }
}

/// Control points every `step` pixels of the circle's projected rim polygon, each moved out to
/// the true circle, with the direction of the projected ellipse's tangent there.
void sample_circle(const Circle& circle, int primitive, const PinholeCamera& camera, const Se3& camera_from_model,
                   const SamplingParams& params, const Window& window, PointSink& points) {
  using std::floor;
  Vec2 rim[kCircleSides + 1];
  real length(0);
  for (int s = 0; s <= kCircleSides; ++s) {
    const Vec3 p = camera_from_model * circle.rim[s];
    if (p.z < params.clipping.near_distance) return;  // a circle crossing the near plane is not tracked
    rim[s] = camera.project(p);
    if (s > 0) length = length + norm(rim[s] - rim[s - 1]);
  }
  const int n = static_cast<int>(floor(length / params.step));
  if (n <= 0) return;
  const Vec3 normal_in_camera = camera_from_model.rotation() * circle.normal;
  const real spacing = length / real(n);
  real target = spacing / real(2), walked(0);
  int side = 0;
  real side_length = norm(rim[1] - rim[0]);
  for (int k = 0; k < n; ++k, target = target + spacing) {
    while (side + 1 < kCircleSides && walked + side_length < target) {
      walked = walked + side_length;
      ++side;
      side_length = norm(rim[side + 1] - rim[side]);
    }
    const real f = side_length > real(0) ? (target - walked) / side_length : real(0);
    const Vec3 chord = circle.rim[side] + f * (circle.rim[side + 1] - circle.rim[side]);
    // Divided by the radius first, so that the unit vector keeps every `real`'s resolution.
    const Vec3 point = circle.centre + circle.radius * normalized((real(1) / circle.radius) * (chord - circle.centre));
    const Vec3 p = camera_from_model * point;
    const Vec2 pixel = camera.project(p);
    if (!window.contains(pixel)) continue;
    // The image tangent: the projection's derivative applied to the 3D tangent n x (p - c), here
    // divided by the depth. A unit tangent and p / z keep every term near 1: in S47.16 products
    // of centimetres keep a hundred steps and turned the direction by 5 mrad.
    const Vec3 tangent = normalized(cross(normal_in_camera, camera_from_model.rotation() * (point - circle.centre)));
    const real x_over_z = p.x / p.z, y_over_z = p.y / p.z;
    Vec2 along{camera.px * (tangent.x - x_over_z * tangent.z), camera.py * (tangent.y - y_over_z * tangent.z)};
    if (camera.distorted()) along = camera.distort_direction(camera.to_pixel(Vec2{x_over_z, y_over_z}), along);
    const real along_length = norm(along);
    if (!(along_length > real(0))) continue;
    const Vec2 direction{along.x / along_length, along.y / along_length};
    points.push_back(make_point(primitive, point, pixel, direction));
  }
}

/// Every primitive's points, or with `faces` those of the primitives it tracks, up to
/// params.max_points; returns the points left out.
size_t sample_primitives(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                         const SamplingParams& params, const FaceVisibility* faces, std::vector<ControlPoint>& kept) {
  kept.clear();
  PointSink points(kept, params.max_points);
  const auto wanted = [faces](int primitive) { return faces == nullptr || faces->edge_tracked(primitive); };
  const Window window{real(params.border), real(camera.width - 1 - params.border), real(params.border),
                      real(camera.height - 1 - params.border)};
  for (size_t e = 0; e < model.edges.size(); ++e)
    if (wanted(static_cast<int>(e)))
      sample_segment(model.vertices[model.edges[e].a], model.vertices[model.edges[e].b], static_cast<int>(e), camera,
                     camera_from_model, params, window, points);
  const Vec3 centre = camera_centre_in_model(camera_from_model);
  for (size_t c = 0; c < model.cylinders.size(); ++c) {
    Vec3 lines[2][2];
    if (!cylinder_generators(model.cylinders[c], centre, lines)) continue;
    for (int k = 0; k < 2; ++k) {
      const int primitive = cylinder_primitive(model, static_cast<int>(c), k);
      if (wanted(primitive))
        sample_segment(lines[k][0], lines[k][1], primitive, camera, camera_from_model, params, window, points);
    }
  }
  for (size_t k = 0; k < model.circles.size(); ++k) {
    const int primitive = circle_primitive(model, static_cast<int>(k));
    if (wanted(primitive)) sample_circle(model.circles[k], primitive, camera, camera_from_model, params, window, points);
  }
  return points.left_out();
}

}  // namespace

std::vector<ControlPoint> sample_control_points(const EdgeModel& model, const PinholeCamera& camera,
                                                const Se3& camera_from_model, const SamplingParams& params) {
  std::vector<ControlPoint> points;
  sample_control_points(model, camera, camera_from_model, params, points);
  return points;
}

size_t sample_control_points(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                             const SamplingParams& params, std::vector<ControlPoint>& points) {
  return sample_primitives(model, camera, camera_from_model, params, nullptr, points);
}

size_t sample_control_points(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                             const SamplingParams& params, const FaceVisibility& faces,
                             std::vector<ControlPoint>& points) {
  return sample_primitives(model, camera, camera_from_model, params, &faces, points);
}

std::vector<ControlPoint> keep_visible(const std::vector<ControlPoint>& points, const EdgeIdBuffer& edge_ids) {
  std::vector<ControlPoint> visible;
  keep_visible(points, edge_ids, visible);
  return visible;
}

void keep_visible(const std::vector<ControlPoint>& points, const EdgeIdBuffer& edge_ids,
                  std::vector<ControlPoint>& visible) {
  visible.clear();
  visible.reserve(points.size());
  for (const ControlPoint& p : points)
    if (edge_ids.shows(p.edge, p.pixel, p.direction)) visible.push_back(p);
}

void keep_visible(std::vector<ControlPoint>& points, const EdgeIdBuffer& edge_ids) {
  points.erase(std::remove_if(points.begin(), points.end(),
                              [&edge_ids](const ControlPoint& p) { return !edge_ids.shows(p.edge, p.pixel, p.direction); }),
               points.end());
}

void project_points(const std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& camera_from_model,
                    ProjectedPoints& out) {
  // Every slot is written: resized, not filled first. The arrays through local pointers: a
  // store to in_front (bytes) could alias the vectors' own pointers.
  const size_t count = points.size();
  out.in_camera.resize(count);
  out.pixel.resize(count);
  out.in_front.resize(count);
  Vec3* in_camera_out = out.in_camera.data();
  Vec2* pixel_out = out.pixel.data();
  unsigned char* in_front_out = out.in_front.data();
  const bool through_lens = camera.distorted();
  for (size_t p = 0; p < count; ++p) {
    const Vec3 in_camera = camera_from_model * points[p].point_in_model;
    const bool in_front = in_camera.z > real(0);
    Vec2 pixel{real(0), real(0)};
    if (in_front) pixel = through_lens ? camera.project_through_lens(in_camera) : camera.project_without_lens(in_camera);
    in_camera_out[p] = in_camera;
    pixel_out[p] = pixel;
    in_front_out[p] = in_front;
  }
}

}  // namespace edgetrack
