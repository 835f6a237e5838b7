// SPDX-License-Identifier: BSD-3-Clause
/// Templates from the model's projected, visible edge points.
#include "edgetrack/detector/template_set.h"

#include <cmath>
#include <cstdio>

#include "edgetrack/control_points.h"
#include "edgetrack/detector/gradient_orientations.h"
#include "edgetrack/edge_id_buffer.h"

namespace edgetrack {

namespace {

struct Candidate {
  int x = 0;
  int y = 0;
  int bin = 0;
  bool outline = false;  ///< on the model's outline against the background
};

/// True when primitive `index` is on the outline seen from `eye` (model frame): an edge between a
/// face turned towards the eye and one turned away, an edge of one face only, or a cylinder's
/// silhouette. The outline shows against any background; an edge between two visible faces shows
/// only as far as the light shades them differently.
bool on_outline(const EdgeModel& model, int index, const Vec3& eye) {
  if (index >= static_cast<int>(model.edges.size())) return index < circle_primitive(model, 0);
  const Edge& edge = model.edges[static_cast<size_t>(index)];
  if (edge.faces[0] < 0 || edge.faces[1] < 0) return true;
  const Vec3& p = model.vertices[static_cast<size_t>(edge.a)];
  auto facing = [&](int f) { return dot(model.faces[static_cast<size_t>(f)].normal, eye - p) > real(0); };
  return facing(edge.faces[0]) != facing(edge.faces[1]);
}

/// The visible edge points of one view as whole pixels with the bin of their edge's normal.
void view_candidates(const EdgeModel& model, const PinholeCamera& camera, const Se3& pose, const TemplateParams& params,
                     EdgeIdBuffer& edge_ids, std::vector<Candidate>& out) {
  using std::floor;
  out.clear();
  edge_ids.render(model, pose);
  SamplingParams sampling;
  sampling.step = params.sample_step;
  sampling.border = 2;
  const Vec3 eye = pose.inverse().translation();
  for (const ControlPoint& p : keep_visible(sample_control_points(model, camera, pose, sampling), edge_ids)) {
    Candidate c;
    c.outline = on_outline(model, p.edge, eye);
    c.x = static_cast<int>(floor(p.pixel.x + real(0.5)));
    c.y = static_cast<int>(floor(p.pixel.y + real(0.5)));
    c.bin = orientation_bin(static_cast<int32_t>(p.normal.x * real(1024)), static_cast<int32_t>(p.normal.y * real(1024)));
    out.push_back(c);
  }
}

/// Farthest-point selection: `count` candidates, each the farthest from those already taken,
/// starting from the first outline point; spreads features evenly over the visible edges, an
/// inner edge point counting as 4 times nearer than it is, so that the outline is preferred.
std::vector<Candidate> spread_selection(const std::vector<Candidate>& candidates, int count) {
  if (static_cast<int>(candidates.size()) <= count) return candidates;
  std::vector<int32_t> nearest(candidates.size(), INT32_MAX);
  std::vector<Candidate> chosen;
  size_t next = 0;
  while (next < candidates.size() && !candidates[next].outline) ++next;
  if (next == candidates.size()) next = 0;
  while (static_cast<int>(chosen.size()) < count) {
    chosen.push_back(candidates[next]);
    int32_t farthest = -1;
    for (size_t i = 0; i < candidates.size(); ++i) {
      const int32_t dx = candidates[i].x - candidates[next].x, dy = candidates[i].y - candidates[next].y;
      const int32_t d = dx * dx + dy * dy;
      if (d < nearest[i]) nearest[i] = d;
    }
    for (size_t i = 0; i < candidates.size(); ++i) {
      // An inner point competes with its distance shrunk 16 times (4 times nearer).
      const int32_t d = candidates[i].outline ? nearest[i] : nearest[i] / 16;
      if (d > farthest) {
        farthest = d;
        next = i;
      }
    }
  }
  return chosen;
}

/// The template of one view from its chosen features; false when they span more than a byte.
bool build_template(const std::vector<Candidate>& chosen, const ViewPose& view, const PinholeCamera& camera,
                    const ModelExtent& extent, TemplateSet& set) {
  int x0 = chosen[0].x, y0 = chosen[0].y, x1 = x0, y1 = y0;
  for (const Candidate& c : chosen) {
    x0 = c.x < x0 ? c.x : x0;
    y0 = c.y < y0 ? c.y : y0;
    x1 = c.x > x1 ? c.x : x1;
    y1 = c.y > y1 ? c.y : y1;
  }
  if (x1 - x0 > 255 || y1 - y0 > 255) return false;
  Template t;
  t.theta_u = view.camera_from_model.theta_u();
  t.distance = (view.camera_from_model * extent.centre).z;
  t.distance_index = view.distance_index;
  const Vec2 centre = camera.project(view.camera_from_model * extent.centre);
  t.anchor = {centre.x - real(x0), centre.y - real(y0)};
  t.width = x1 - x0 + 1;
  t.height = y1 - y0 + 1;
  t.first = static_cast<int>(set.features.size());
  t.count = static_cast<int>(chosen.size());
  for (const Candidate& c : chosen) {
    TemplateFeature f;
    f.x = static_cast<uint8_t>(c.x - x0);
    f.y = static_cast<uint8_t>(c.y - y0);
    f.bin = static_cast<uint8_t>(c.bin);
    set.features.push_back(f);
  }
  set.templates.push_back(t);
  return true;
}

uint32_t fnv1a(uint32_t hash, long long value) {
  for (int i = 0; i < 8; ++i) {
    hash ^= static_cast<uint32_t>((static_cast<unsigned long long>(value) >> (8 * i)) & 0xffu);
    hash *= 16777619u;
  }
  return hash;
}

long long micrometres(const real& metres) { return std::llround(static_cast<double>(metres) * 1e6); }

}  // namespace

Se3 template_pose(const Template& t, const ModelExtent& extent) {
  const Se3 rotation = Se3::from_theta_u(Vec3{}, t.theta_u);
  return Se3(rotation.rotation(), Vec3{real(0), real(0), t.distance} - rotation.rotation() * extent.centre);
}

int detection_reduction(const PinholeCamera& camera) {
  const int side = camera.width < camera.height ? camera.width : camera.height;
  return side <= kMaxDetectionSide ? 1 : (side + kMaxDetectionSide - 1) / kMaxDetectionSide;
}

PinholeCamera detection_camera(const PinholeCamera& camera) {
  return downscaled_camera(camera, detection_reduction(camera));
}

PinholeCamera TemplateSet::detection_camera() const { return edgetrack::detection_camera(camera); }

PinholeCamera TemplateSet::matching_camera() const { return downscaled_camera(detection_camera(), params.downscale); }

size_t TemplateSet::memory_bytes() const {
  return templates.size() * sizeof(Template) + features.size() * sizeof(TemplateFeature);
}

std::string model_fingerprint(const EdgeModel& model) {
  uint32_t hash = 2166136261u;
  for (const Vec3& v : model.vertices)
    hash = fnv1a(fnv1a(fnv1a(hash, micrometres(v.x)), micrometres(v.y)), micrometres(v.z));
  for (const Face& f : model.faces)
    for (int i : f.vertices) hash = fnv1a(hash, i);
  for (const Edge& e : model.edges) hash = fnv1a(fnv1a(hash, e.a), e.b);
  for (const Cylinder& c : model.cylinders) hash = fnv1a(hash, micrometres(c.radius));
  for (const Circle& c : model.circles) hash = fnv1a(hash, micrometres(c.radius));
  char text[64];
  std::snprintf(text, sizeof text, "v%zu-e%zu-%08x", model.vertices.size(), model.edges.size(), hash);
  return text;
}

Result<bool> check_template_params(const TemplateParams& p) {
  auto bad = [](const std::string& what) { return Error{"", 0, "template parameter out of range: " + what}; };
  if (p.views.subdivisions < 0 || p.views.subdivisions > 4) return bad("subdivisions must be 0 to 4");
  if (p.views.in_plane_steps < 1 || p.views.in_plane_steps > 360) return bad("in-plane steps must be 1 to 360");
  if (!(p.views.max_angle >= real(0))) return bad("the view cone's angle must be >= 0");
  if (p.views.distance_min < real(0) || p.views.distance_max < p.views.distance_min)
    return bad("distances must satisfy 0 <= min <= max");
  if (p.views.distance_min == real(0) && p.views.distance_max != real(0))
    return bad("a maximum distance needs a minimum distance");
  if (!(p.views.distance_ratio > real(1.01)) || p.views.distance_ratio > real(4))
    return bad("the distance ratio must be over 1.01 and at most 4");
  if (p.downscale < 1 || p.downscale > 4) return bad("downscale must be 1 to 4");
  if (p.features < 4 || p.features > 63) return bad("features must be 4 to 63");
  if (p.min_features < 4 || p.min_features > p.features) return bad("min features must be 4 to features");
  if (!(p.sample_step >= real(1)) || p.sample_step > real(20)) return bad("the sample step must be 1 to 20 px");
  return true;
}

Result<TemplateSet> make_template_set(const EdgeModel& model, const PinholeCamera& camera,
                                      const TemplateParams& params) {
  auto checked = check_template_params(params);
  if (!checked.ok()) return checked.error();
  TemplateSet set;
  set.params = params;
  set.camera = camera;
  set.extent = model_extent(model);
  set.model_fingerprint = model_fingerprint(model);
  // The range is checked and spread in the pixels detection sees (its model-size bound).
  const PinholeCamera detecting = set.detection_camera();
  const PinholeCamera small = set.matching_camera();
  if (small.width < 16 || small.height < 16) return Error{"", 0, "the downscaled image is under 16 x 16 pixels"};
  const Result<long long> views = checked_view_count(params.views, detecting, set.extent);
  if (!views.ok()) return views.error();
  EdgeIdBuffer edge_ids(small);
  std::vector<Candidate> candidates;
  for (const ViewPose& view : view_poses(params.views, detecting, set.extent)) {
    view_candidates(model, small, view.camera_from_model, params, edge_ids, candidates);
    if (static_cast<int>(candidates.size()) < params.min_features) continue;
    build_template(spread_selection(candidates, params.features), view, small, set.extent, set);
  }
  set.distance_count = static_cast<int>(view_distances(params.views, detecting, set.extent).size());
  if (set.templates.empty()) return Error{"", 0, "no view of the range shows enough of the model's edges"};
  return set;
}

}  // namespace edgetrack
