// SPDX-License-Identifier: BSD-3-Clause
/// The detector's evaluation on generated QVGA frames: the cube or the wood toy at random poses
/// inside the template range over a textured background with distractor lines behind it (or the
/// background and lines alone), detected with the default DetectorParams. The range: views
/// within 60 degrees of the model's z axis, 120 to 200 mm from its centre (the paper's set-up is
/// at 150 mm), any in-plane angle, the model wholly in view. Prints one line per trial and a
/// summary of key=value pairs for results.sh. Each detection is wrapped in a count window, so
/// under toolchains/qemu/count-insns.sh the windows hold the guest instructions of detection only.
///
/// usage: bench_detection cube|wood_toy TRIALS [--no-object] [--from-truth] [--subdivisions N]
///        [--in-plane N] [--seed S] [--quiet]
/// --from-truth also runs the refinement's tracking from the true pose (how often the tracker
/// itself keeps a single frame within 2 mm and 2 degrees: the ceiling of the detection rate).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

#include "count_markers.h"
#include "detection_scene.h"
#include "edgetrack/detector/detector.h"
#include "edgetrack/model_io.h"
#include "synthetic_sequence.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kLines = 12;
constexpr double kRightMm = 2, kRightDeg = 2;

struct Options {
  Scene scene = Scene::kCube;
  int trials = 20;
  bool with_object = true;
  bool from_truth = false;
  TemplateParams templates;
  uint32_t seed = 1;
  bool quiet = false;
};

bool parse(int argc, char** argv, Options& o) {
  if (argc < 3) return false;
  if (std::strcmp(argv[1], "wood_toy") == 0) o.scene = Scene::kWoodToy;
  else if (std::strcmp(argv[1], "cube") != 0) return false;
  o.trials = std::atoi(argv[2]);
  o.templates.views.max_angle = real(60.0 * M_PI / 180);
  o.templates.views.distance_min = real(0.12);
  o.templates.views.distance_max = real(0.2);
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if (a == "--no-object") o.with_object = false;
    else if (a == "--from-truth") o.from_truth = true;
    else if (a == "--quiet") o.quiet = true;
    else if (a == "--subdivisions" && value) o.templates.views.subdivisions = std::atoi(argv[++i]);
    else if (a == "--in-plane" && value) o.templates.views.in_plane_steps = std::atoi(argv[++i]);
    else if (a == "--seed" && value) o.seed = static_cast<uint32_t>(std::atoi(argv[++i]));
    else return false;
  }
  return o.trials > 0;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool within(const PoseError& e) { return e.centre_mm <= kRightMm && e.rotation_deg <= kRightDeg; }

/// Six frames of the tracker on `frame` from the true pose, each from the last one's pose.
PoseError tracked_from_truth(Tracker& tracker, const uint16_t* frame, int camera_width, int camera_height,
                             const Se3& truth, const Vec3& centre, const std::vector<Mat33>& symmetries) {
  Se3 pose = truth;
  for (int k = 0; k < 6; ++k) {
    tracker.reset(pose);
    const Result<FrameResult> result = tracker.track(packed_frame(frame, camera_width, camera_height, PixelLayout::kRgb565));
    if (result.ok()) pose = result.value().camera_from_model;
  }
  return pose_error(pose, truth, centre, symmetries);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr, "usage: bench_detection cube|wood_toy TRIALS [--no-object] [--from-truth] [--subdivisions N] "
                         "[--in-plane N] [--seed S] [--quiet]\n");
    return 2;
  }
  const Result<EdgeModel> model = load_model(model_path(o.scene));
  if (!model.ok()) {
    std::fprintf(stderr, "%s\n", model.error().text().c_str());
    return 1;
  }
  const PinholeCamera camera = qvga_camera();
  auto start = std::chrono::steady_clock::now();
  Result<TemplateSet> templates = make_template_set(model.value(), camera, o.templates);
  if (!templates.ok()) {
    std::fprintf(stderr, "%s\n", templates.error().text().c_str());
    return 1;
  }
  const double make_ms = ms_since(start);
  const size_t template_count = templates.value().templates.size(), bytes = templates.value().memory_bytes();
  const ModelExtent extent = templates.value().extent;
  Result<Detector> detector =
      Detector::create(model.value(), camera, std::move(templates).value(), DetectorParams{}, TrackerParams{});
  Result<Tracker> tracker = Tracker::create(model.value(), camera, random_view(model.value(), camera, o.templates.views, 1),
                                            TrackerParams{});
  if (!detector.ok() || !tracker.ok()) {
    std::fprintf(stderr, "%s\n", (detector.ok() ? tracker.error() : detector.error()).text().c_str());
    return 1;
  }
  const std::vector<Mat33> symmetries = o.scene == Scene::kCube ? cube_symmetries() : std::vector<Mat33>{Mat33::identity()};
  int found = 0, right = 0, refined = 0, truth_kept = 0;
  double total_ms = 0, worst_ms = 0, cpu_ms = 0;
  Rgb565Frame frame;
  for (int k = 0; k < o.trials; ++k) {
    const uint32_t seed = o.seed * 100003u + static_cast<uint32_t>(k);
    const Se3 truth = random_view(model.value(), camera, o.templates.views, seed);
    render_trial(model.value(), camera, truth, o.with_object, kLines, seed, frame);
    start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    edgetrack_count_begin();
    const Detection d = detector.value().detect(packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565)).value();
    edgetrack_count_end();
    const double ms = ms_since(start);
    cpu_ms += 1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    total_ms += ms;
    worst_ms = std::fmax(worst_ms, ms);
    const PoseError e = pose_error(d.camera_from_model, truth, extent.centre, symmetries);
    const bool ok = d.found && o.with_object && within(e);
    found += d.found;
    right += ok;
    refined += static_cast<int>(d.refined.size());
    if (o.from_truth && o.with_object)
      truth_kept += within(tracked_from_truth(tracker.value(), frame.pixels.data(), frame.width, frame.height, truth,
                                              extent.centre, symmetries));
    if (!o.quiet)
      std::printf("trial %d (%.0f mm): found %d right %d score %.2f match %.2f candidates %zu error %.2f mm %.2f deg "
                  "%.1f ms\n",
                  k, 1000 * static_cast<double>((truth * extent.centre).z), d.found, ok, static_cast<double>(d.score),
                  static_cast<double>(d.match_share), d.refined.size(), e.centre_mm, e.rotation_deg, ms);
  }
  std::printf("detection: scene=%s object=%d trials=%d found=%d right=%d rate_percent=%.1f wrong=%d truth_kept=%d "
              "templates=%zu template_bytes=%zu make_ms=%.0f mean_ms=%.2f worst_ms=%.2f cpu_ms=%.2f "
              "refined_per_trial=%.1f real=%s\n",
              o.scene == Scene::kCube ? "cube" : "wood_toy", o.with_object, o.trials, found, right,
              100.0 * right / o.trials, found - right, o.from_truth ? truth_kept : -1, template_count, bytes, make_ms,
              total_ms / o.trials, worst_ms, cpu_ms / o.trials, static_cast<double>(refined) / o.trials, real_name());
  return 0;
}
