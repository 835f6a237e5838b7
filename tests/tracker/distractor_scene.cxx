// SPDX-License-Identifier: BSD-3-Clause
/// The distractor-bar scenes: bars built as closed boxes, joined with the tracked model's
/// polygons and rendered with SceneRenderer::render.
#include "distractor_scene.h"

#include <cmath>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"

using namespace edgetrack;

namespace edgetrack_test {
namespace {

/// Appends the box with corner `start` and edges `along`, `out` and `side` to `polygons`.
void add_box(const Vec3& start, const Vec3& along, const Vec3& out, const Vec3& side, Polygons& polygons) {
  const int first = static_cast<int>(polygons.vertices.size());
  for (int k = 0; k < 8; ++k)
    polygons.vertices.push_back(start + ((k & 1) ? along : Vec3{}) + ((k & 2) ? out : Vec3{}) +
                                ((k & 4) ? side : Vec3{}));
  // The six faces, each as four corners in boundary order.
  const int faces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (const auto& face : faces) {
    polygons.faces.push_back({first + face[0], first + face[1], first + face[2], first + face[3]});
    polygons.face_attributes.emplace_back();
  }
}

}  // namespace

EdgeModel with_distractor_bars(const EdgeModel& model, real offset, real width) {
  Polygons polygons;
  polygons.vertices = model.vertices;
  for (const Face& face : model.faces) {
    polygons.faces.push_back(face.vertices);
    polygons.face_attributes.push_back(face.attributes);
  }
  const real half(0.5), thickness(0.0005);
  for (const Edge& edge : model.edges) {
    if (edge.faces[0] < 0) continue;
    const Face& face = model.faces[static_cast<size_t>(edge.faces[0])];
    Vec3 face_centre;
    for (int v : face.vertices) face_centre = face_centre + model.vertices[static_cast<size_t>(v)];
    face_centre = (real(1) / real(static_cast<int>(face.vertices.size()))) * face_centre;
    const Vec3 a = model.vertices[static_cast<size_t>(edge.a)], b = model.vertices[static_cast<size_t>(edge.b)];
    const Vec3 along = b - a;
    Vec3 out = normalized(cross(face.normal, along));
    if (dot(out, half * (a + b) - face_centre) < real(0)) out = -out;
    // In the face's plane, beyond the edge: it hides none of the model's edges.
    add_box(a + offset * out - half * thickness * face.normal, along, width * out, thickness * face.normal, polygons);
  }
  const Result<EdgeModel> built = build_edge_model(polygons, EdgeRules{}, "distractor bars");
  return built.ok() ? built.value() : model;
}

DistractorRun run_with_distractors(Scene scene, int frames, const TrackerParams& params, real offset, real width) {
  DistractorRun run;
  const Result<EdgeModel> model = load_model(model_path(scene));
  if (!model.ok()) return run;
  const EdgeModel scene_model = with_distractor_bars(model.value(), offset, width);
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(scene, frames);
  Result<Tracker> tracker = Tracker::create(model.value(), camera, truth[0], params);
  if (!tracker.ok()) return run;
  run.loaded = true;
  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame frame;
  double alternatives = 0;
  for (int k = 0; k < frames; ++k) {
    renderer.render(scene_model, truth[k], static_cast<uint32_t>(1000 + k), frame);
    const FrameResult result = tracker.value().track(rgb565_view(frame)).value();
    run.poses.push_back(result.camera_from_model);
    const Vec3 d = camera_position(result.camera_from_model) - camera_position(truth[k]);
    const double error_mm = 1000 * std::sqrt(static_cast<double>(d.x) * static_cast<double>(d.x) +
                                             static_cast<double>(d.y) * static_cast<double>(d.y) +
                                             static_cast<double>(d.z) * static_cast<double>(d.z));
    run.position_error_mm.push_back(error_mm);
    run.mean_position_error_mm += error_mm / frames;
    run.largest_position_error_mm = std::fmax(run.largest_position_error_mm, error_mm);
    int count = 0;
    for (const EdgeMatch& m : tracker.value().matches()) count += m.alternative_count;
    const size_t matches = tracker.value().matches().size();
    alternatives += matches ? double(count) / double(matches) / frames : 0;
  }
  run.mean_alternatives = alternatives;
  return run;
}

}  // namespace edgetrack_test
