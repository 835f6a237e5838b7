// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's face angle rule with hysteresis, view clipping and level of detail.
#include "edgetrack/face_visibility.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/control_points.h"

namespace edgetrack {
namespace {

/// The nearest the sampler ever projects from (metres): a user's near plane of 0 would divide by 0.
const real kClosest = real(1e-4);
const real kDefaultNear = real(0.01);

/// One half-space of the view, inside where dot(normal, p) + offset >= 0 (camera frame).
struct HalfSpace {
  Vec3 normal;
  real offset{0};
  real at(const Vec3& p) const { return dot(normal, p) + offset; }
};

/// The half-spaces `clipping` asks for; returns how many were written into `out` (at most 6).
int view_half_spaces(const PinholeCamera& camera, const ViewClipping& clipping, HalfSpace out[6]) {
  int n = 0;
  out[n++] = {{real(0), real(0), real(1)}, -clipping.near_distance};
  if (clipping.far_clipping) out[n++] = {{real(0), real(0), real(-1)}, clipping.far_distance};
  if (clipping.fov_clipping) {
    // u = u0 + px x / z >= 0  <=>  px x + u0 z >= 0 (z > 0), and likewise for the other borders.
    const real w(camera.width), h(camera.height);
    out[n++] = {{camera.px, real(0), camera.u0}, real(0)};
    out[n++] = {{-camera.px, real(0), w - camera.u0}, real(0)};
    out[n++] = {{real(0), camera.py, camera.v0}, real(0)};
    out[n++] = {{real(0), -camera.py, h - camera.v0}, real(0)};
  }
  return n;
}

/// Sutherland-Hodgman: the part of polygon `in` inside `plane`, into `out`.
void clip_polygon(const std::vector<Vec3>& in, const HalfSpace& plane, std::vector<Vec3>& out) {
  out.clear();
  for (size_t i = 0; i < in.size(); ++i) {
    const Vec3& p = in[i];
    const Vec3& q = in[(i + 1) % in.size()];
    const real fp = plane.at(p), fq = plane.at(q);
    if (fp >= real(0)) out.push_back(p);
    if ((fp >= real(0)) != (fq >= real(0))) out.push_back(p + (fp / (fp - fq)) * (q - p));
  }
}

}  // namespace

ViewClipping view_clipping(const FaceVisibilityParams& params) {
  ViewClipping clipping;
  clipping.near_distance = params.near_clipping ? std::max(params.near_distance, kClosest) : kDefaultNear;
  clipping.far_clipping = params.far_clipping;
  clipping.far_distance = params.far_distance;
  clipping.fov_clipping = params.fov_clipping;
  return clipping;
}

bool clip_to_view(const Vec3& a, const Vec3& b, const PinholeCamera& camera, const ViewClipping& clipping, real& t0,
                  real& t1) {
  HalfSpace planes[6];
  const int n = view_half_spaces(camera, clipping, planes);
  t0 = real(0);
  t1 = real(1);
  for (int i = 0; i < n; ++i) {
    const real fa = planes[i].at(a), fb = planes[i].at(b);
    if (fa < real(0) && fb < real(0)) return false;
    if (fa < real(0)) t0 = std::max(t0, fa / (fa - fb));
    else if (fb < real(0)) t1 = std::min(t1, fa / (fa - fb));
  }
  return t0 < t1;
}

FaceVisibility::FaceVisibility(const EdgeModel& model)
    : face_visible_(model.faces.size(), 0), edge_tracked_(static_cast<size_t>(primitive_count(model)), 0),
      edge_count_(model.edges.size()) {
  size_t most = 4;  // a circle's bounding square
  for (const Face& face : model.faces) most = std::max(most, face.vertices.size());
  polygon_.reserve(most + 6);  // each clipping plane adds at most one vertex
  clipped_.reserve(most + 6);
  reset();
}

void FaceVisibility::reset() {
  std::fill(face_visible_.begin(), face_visible_.end(), 0);
  // Edges follow their faces; cylinders are always tracked, circles unless level of detail drops them.
  std::fill(edge_tracked_.begin(), edge_tracked_.begin() + static_cast<long>(edge_count_), 0);
  std::fill(edge_tracked_.begin() + static_cast<long>(edge_count_), edge_tracked_.end(), 1);
}

real FaceVisibility::clipped_area(const EdgeModel& model, int face, const PinholeCamera& camera,
                                  const Se3& camera_from_model, const ViewClipping& clipping) {
  polygon_.clear();
  for (int v : model.faces[static_cast<size_t>(face)].vertices)
    polygon_.push_back(camera_from_model * model.vertices[static_cast<size_t>(v)]);
  return clipped_polygon_area(camera, clipping);
}

real FaceVisibility::clipped_square_area(const Circle& circle, const PinholeCamera& camera,
                                         const Se3& camera_from_model, const ViewClipping& clipping) {
  // ViSP's polygon of a circle: the square about it in its plane, two sides along the direction
  // from its centre to its first plane point (where the rim starts).
  const Vec3 x = circle.rim[0] - circle.centre, z = circle.radius * normalized(cross(x, circle.normal));
  polygon_.clear();
  for (const Vec3& corner : {circle.centre + x + z, circle.centre + x - z, circle.centre - x - z, circle.centre - x + z})
    polygon_.push_back(camera_from_model * corner);
  return clipped_polygon_area(camera, clipping);
}

real FaceVisibility::clipped_polygon_area(const PinholeCamera& camera, const ViewClipping& clipping) {
  HalfSpace planes[6];
  const int n = view_half_spaces(camera, clipping, planes);
  for (int i = 0; i < n && !polygon_.empty(); ++i) {
    clip_polygon(polygon_, planes[i], clipped_);
    polygon_.swap(clipped_);
  }
  real twice_area(0);  // the shoelace formula over the projected polygon
  for (size_t i = 0; i < polygon_.size(); ++i) {
    const Vec2 p = camera.project(polygon_[i]), q = camera.project(polygon_[(i + 1) % polygon_.size()]);
    twice_area += p.x * q.y - q.x * p.y;
  }
  using std::fabs;
  return fabs(twice_area) / 2;
}

bool FaceVisibility::face_passes(const EdgeModel& model, int face, const PinholeCamera& camera,
                                 const Se3& camera_from_model, const real& cos_limit,
                                 const FaceVisibilityParams& params) {
  const Face& f = model.faces[static_cast<size_t>(face)];
  Vec3 centre;
  for (int v : f.vertices) centre = centre + camera_from_model * model.vertices[static_cast<size_t>(v)];
  centre = (real(1) / real(static_cast<int>(f.vertices.size()))) * centre;
  const Vec3 normal = camera_from_model.rotation() * f.normal;
  // angle < limit  <=>  cos(angle) > cos(limit), with cos(angle) = (-centre . normal) / |centre|.
  if (!(dot(-centre, normal) > cos_limit * norm(centre))) return false;
  // A face's own useLod= and minPolygonAreaThreshold= override the general setting (ViSP's <lod>).
  return !f.attributes.use_lod.value_or(params.use_lod) ||
         clipped_area(model, face, camera, camera_from_model, view_clipping(params)) >=
             f.attributes.min_polygon_area.value_or(params.min_polygon_area);
}

void FaceVisibility::update(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                            const FaceVisibilityParams& params) {
  using std::cos;
  const real cos_appear = cos(params.angle_appear), cos_disappear = cos(params.angle_disappear);
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const bool was_visible = face_visible_[f] != 0;
    face_visible_[f] = face_passes(model, static_cast<int>(f), camera, camera_from_model,
                                   was_visible ? cos_disappear : cos_appear, params);
  }
  const ViewClipping clipping = view_clipping(params);
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const Edge& edge = model.edges[e];
    bool tracked = false;
    if (edge.faces[0] < 0 && edge.faces[1] < 0) {
      tracked = true;
      if (edge.attributes.use_lod.value_or(params.use_lod)) {
        const Vec3 a = camera_from_model * model.vertices[static_cast<size_t>(edge.a)];
        const Vec3 b = camera_from_model * model.vertices[static_cast<size_t>(edge.b)];
        real t0, t1;
        tracked = clip_to_view(a, b, camera, clipping, t0, t1) &&
                  norm(camera.project(a + t1 * (b - a)) - camera.project(a + t0 * (b - a))) >=
                      edge.attributes.min_line_length.value_or(params.min_line_length);
      }
    } else {
      for (int f : edge.faces)
        if (f >= 0 && face_visible_[static_cast<size_t>(f)]) tracked = true;
    }
    edge_tracked_[e] = tracked;
  }
  // A circle by its square (ViSP's four-point polygon about it): with level of detail, tracked
  // when the square's clipped image covers at least the area threshold. A cylinder stays
  // tracked: ViSP gives it the polygons of its axis and of a box about it, but tracks it while
  // one of the box's faces is visible, and those have no orientation, which makes them visible
  // before any level-of-detail test (vpMbtPolygon::isVisible).
  for (size_t k = 0; k < model.circles.size(); ++k) {
    const Circle& circle = model.circles[k];
    edge_tracked_[static_cast<size_t>(circle_primitive(model, static_cast<int>(k)))] =
        !circle.attributes.use_lod.value_or(params.use_lod) ||
        clipped_square_area(circle, camera, camera_from_model, clipping) >=
            circle.attributes.min_polygon_area.value_or(params.min_polygon_area);
  }
}

}  // namespace edgetrack
