// SPDX-License-Identifier: BSD-3-Clause
/// The detector's evaluation on generated QVGA frames: the cube or the wood toy at random poses
/// inside the template range over a textured background with distractor lines (or the
/// background and lines alone), detected with the default DetectorParams. Prints one line per
/// trial and a summary of key=value pairs for results.sh. Detection calls are wrapped in count
/// windows, so under toolchains/qemu/count-insns.sh the guest instructions are of detection only.
///
/// usage: bench_detection cube|wood_toy TRIALS [--no-object] [--subdivisions N] [--in-plane N]
///        [--cone DEG] [--distance MIN:MAX] [--lines N] [--seed S] [--quiet]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "count_markers.h"
#include "detection_scene.h"
#include "edgetrack/detector/detector.h"
#include "edgetrack/model_io.h"
#include "synthetic_sequence.h"
#include "edgetrack/control_points.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

struct Options {
  Scene scene = Scene::kCube;
  int trials = 20;
  bool with_object = true;
  TemplateParams templates;
  int lines = 12;
  uint32_t seed = 1;
  bool quiet = false;
};

bool parse(int argc, char** argv, Options& o) {
  if (argc < 3) return false;
  if (std::strcmp(argv[1], "wood_toy") == 0) o.scene = Scene::kWoodToy;
  else if (std::strcmp(argv[1], "cube") != 0) return false;
  o.trials = std::atoi(argv[2]);
  // The evaluation's range: views from above the model's xy plane (at least 15 degrees up).
  o.templates.views.max_angle = real(75.0 * M_PI / 180);
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if (a == "--no-object") o.with_object = false;
    else if (a == "--quiet") o.quiet = true;
    else if (a == "--subdivisions" && value) o.templates.views.subdivisions = std::atoi(argv[++i]);
    else if (a == "--in-plane" && value) o.templates.views.in_plane_steps = std::atoi(argv[++i]);
    else if (a == "--cone" && value) o.templates.views.max_angle = real(std::atof(argv[++i]) * M_PI / 180);
    else if (a == "--lines" && value) o.lines = std::atoi(argv[++i]);
    else if (a == "--distance" && value) {
      double low = 0, high = 0;
      if (std::sscanf(argv[++i], "%lf:%lf", &low, &high) != 2) return false;
      o.templates.views.distance_min = real(low);
      o.templates.views.distance_max = real(high);
    }
    else if (a == "--seed" && value) o.seed = static_cast<uint32_t>(std::atoi(argv[++i]));
    else return false;
  }
  return o.trials > 0;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr, "usage: bench_detection cube|wood_toy TRIALS [--no-object] [--subdivisions N] [--in-plane N] "
                         "[--cone DEG] [--distance MIN:MAX] [--lines N] [--seed S] [--quiet]\n");
    return 2;
  }
  const Result<EdgeModel> model = load_model(model_path(o.scene));
  if (!model.ok()) {
    std::fprintf(stderr, "%s\n", model.error().text().c_str());
    return 1;
  }
  const PinholeCamera camera = qvga_camera();
  auto start = std::chrono::steady_clock::now();
  if (const char* v = std::getenv("FEAT")) o.templates.features = std::atoi(v);
  if (const char* v = std::getenv("RATIO")) o.templates.views.distance_ratio = real(std::atof(v));
  Result<TemplateSet> templates = make_template_set(model.value(), camera, o.templates);
  if (!templates.ok()) {
    std::fprintf(stderr, "%s\n", templates.error().text().c_str());
    return 1;
  }
  const double make_ms = ms_since(start);
  const size_t template_count = templates.value().templates.size(), bytes = templates.value().memory_bytes();
  const ModelExtent extent = templates.value().extent;
  DetectorParams params;
  if (const char* v = std::getenv("WIT")) params.wide_iterations = std::atoi(v);
  if (const char* v = std::getenv("IT")) params.refine_iterations = std::atoi(v);
  if (const char* v = std::getenv("WR")) params.wide_range = std::atoi(v);
  if (const char* v = std::getenv("CAND")) params.matching.max_candidates = std::atoi(v);
  if (const char* v = std::getenv("SHARE")) params.matching.min_share = real(std::atof(v));
  if (const char* v = std::getenv("SPREAD")) params.spread = std::atoi(v);
  if (const char* v = std::getenv("MAG")) params.orientations.min_magnitude = std::atoi(v);
  TrackerParams tracking;
  if (const char* v = std::getenv("HYP")) tracking.hypotheses = std::atoi(v);
  if (const char* v = std::getenv("RANGE")) tracking.me.setRange(static_cast<unsigned>(std::atoi(v)));
  Result<Detector> detector =
      Detector::create(model.value(), camera, std::move(templates).value(), params, tracking);
  if (!detector.ok()) {
    std::fprintf(stderr, "%s\n", detector.error().text().c_str());
    return 1;
  }
  const std::vector<Mat33> symmetries = o.scene == Scene::kCube ? cube_symmetries() : std::vector<Mat33>{Mat33::identity()};
  Result<Tracker> ceiling = Tracker::create(model.value(), camera, random_view(model.value(), camera, o.templates.views, 1), tracking);
  int found = 0, right = 0, refined = 0, truth_kept = 0;
  double total_ms = 0, worst_ms = 0;
  Rgb565Frame frame;
  for (int k = 0; k < o.trials; ++k) {
    const uint32_t seed = o.seed * 100003u + static_cast<uint32_t>(k);
    const Se3 truth = random_view(model.value(), camera, o.templates.views, seed);
    render_trial(model.value(), camera, truth, o.with_object, o.lines, seed, frame);
    start = std::chrono::steady_clock::now();
    edgetrack_count_begin();
    const Detection d = detector.value().detect(frame.pixels.data());
    edgetrack_count_end();
    const double ms = ms_since(start);
    total_ms += ms;
    worst_ms = std::fmax(worst_ms, ms);
    const PoseError e = pose_error(d.camera_from_model, truth, extent.centre, symmetries);
    const double truth_distance = static_cast<double>((truth * extent.centre).z);
    const bool ok = d.found && o.with_object && e.centre_mm <= 2 && e.rotation_deg <= 2;
    if (const char* v = std::getenv("DUMP")) if (std::atoi(v) == k) {
      FILE* out = std::fopen("/tmp/i14x/dump.ppm", "wb"); std::fprintf(out, "P6 320 240 255\n");
      std::vector<uint8_t> rgb(320 * 240 * 3);
      for (int i = 0; i < 320 * 240; ++i) { uint16_t p = frame.pixels[i]; rgb[3*i] = (p >> 11) << 3; rgb[3*i+1] = ((p >> 5) & 63) << 2; rgb[3*i+2] = (p & 31) << 3; }
      EdgeIdBuffer ids(camera); ids.render(model.value(), d.camera_from_model);
      SamplingParams sp; sp.step = real(2);
      for (auto& c : keep_visible(sample_control_points(model.value(), camera, d.camera_from_model, sp), ids)) { int x = (int)c.pixel.x, y = (int)c.pixel.y; if (x >= 0 && x < 320 && y >= 0 && y < 240) { rgb[3*(y*320+x)] = 255; rgb[3*(y*320+x)+1] = 0; rgb[3*(y*320+x)+2] = 0; } }
      std::fwrite(rgb.data(), 1, rgb.size(), out); std::fclose(out);
    }
    if (std::getenv("CANDS")) for (auto& c : d.refined) { PoseError ce = pose_error(pose_of_match(detector.value().templates(), c.match, 4), truth, extent.centre, symmetries); PoseError re = pose_error(c.camera_from_model, truth, extent.centre, symmetries); std::printf("   cand t%d share %.2f (%.1f mm %.1f deg) -> status %d kept %d/%d scale %.2f support %.2f (%.1f mm %.1f deg)\n", c.match.template_index, (double)c.match.share, ce.centre_mm, ce.rotation_deg, (int)c.status, c.kept, c.visible, (double)c.residual_scale, (double)c.support, re.centre_mm, re.rotation_deg); }
    if (std::getenv("CEIL") && o.with_object) {
      FrameResult fr;
      for (int it = 0; it < 6; ++it) { ceiling.value().reset(it == 0 ? truth : fr.camera_from_model); fr = ceiling.value().track(frame.pixels.data()); }
      const PoseError te = pose_error(fr.camera_from_model, truth, extent.centre, symmetries);
      truth_kept += te.centre_mm <= 2 && te.rotation_deg <= 2;
      std::printf("   from truth: %.2f mm %.2f deg status %d\n", te.centre_mm, te.rotation_deg, (int)fr.status);
    }
    found += d.found;
    right += ok;
    refined += static_cast<int>(d.refined.size());
    if (!o.quiet)
      std::printf("trial %d (%.0f mm): found %d right %d score %.2f match %.2f candidates %zu error %.2f mm %.2f deg %.1f ms\n", k,
                  truth_distance * 1000, d.found, ok, static_cast<double>(d.score), static_cast<double>(d.match_share), d.refined.size(),
                  e.centre_mm, e.rotation_deg, ms);
  }
  if (std::getenv("CEIL")) std::printf("tracked from the truth within 2 mm 2 deg: %d\n", truth_kept);
  std::printf("detection: scene=%s object=%d trials=%d found=%d right=%d rate_percent=%.1f false=%d templates=%zu "
              "template_bytes=%zu make_ms=%.0f mean_ms=%.2f worst_ms=%.2f refined_per_trial=%.1f real=%s\n",
              o.scene == Scene::kCube ? "cube" : "wood_toy", o.with_object, o.trials, found, right,
              100.0 * right / o.trials, found - right, template_count, bytes, make_ms, total_ms / o.trials, worst_ms,
              static_cast<double>(refined) / o.trials, real_name());
  return 0;
}
