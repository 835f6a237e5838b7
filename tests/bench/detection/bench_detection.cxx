// SPDX-License-Identifier: BSD-3-Clause
/// The detector's evaluation on generated QVGA frames: the cube or the wood toy at random poses
/// inside the template range over a textured background with distractor lines behind it (or the
/// background and lines alone), detected with the default DetectorParams. The range: views
/// within 60 degrees of the model's z axis, 120 to 200 mm from its centre (the paper's set-up is
/// at 150 mm), any in-plane angle, the model wholly in view. Prints one line per trial and a
/// summary of key=value pairs for results.sh. Each detection is wrapped in a count window, so
/// under toolchains/qemu/count-insns.sh the windows hold the guest instructions of detection only.
///
/// usage: bench_detection cube|wood_toy TRIALS [--no-object] [--from-truth] [--diagnose]
///        [--subdivisions N] [--in-plane N] [--distance-ratio R] [--seed S] [--max-points N] [--quiet]
/// --from-truth also runs the refinement's tracking from the true pose (how often the tracker
/// itself keeps a single frame within 2 mm and 2 degrees: the ceiling of the detection rate),
/// and the detector's own refinement (Detector::refine_from) from the true pose started as a
/// match's is: how often its schedule, from the best start a match could give, stays within.
/// --diagnose says, for each trial that is not right, where it failed (Failure), prints the
/// refined candidates, and counts each failure in the summary. --max-points sets
/// DetectorParams::max_points_searched (the default's otherwise).
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
/// Found farther off than this: a wrong pose, not an imprecise one (docs/results/status.md's
/// "confidently wrong" bound).
constexpr double kFarMm = 5, kFarDeg = 5;

struct Options {
  Scene scene = Scene::kCube;
  int trials = 20;
  bool with_object = true;
  bool from_truth = false;
  TemplateParams templates;
  uint32_t seed = 1;
  bool quiet = false;
  bool diagnose = false;
  int max_points = -1;  ///< -1: the default DetectorParams' budget
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
    else if (a == "--diagnose") o.diagnose = true;
    else if (a == "--subdivisions" && value) o.templates.views.subdivisions = std::atoi(argv[++i]);
    else if (a == "--in-plane" && value) o.templates.views.in_plane_steps = std::atoi(argv[++i]);
    else if (a == "--distance-ratio" && value) o.templates.views.distance_ratio = real(std::atof(argv[++i]));
    else if (a == "--seed" && value) o.seed = static_cast<uint32_t>(std::atoi(argv[++i]));
    else if (a == "--max-points" && value) o.max_points = std::atoi(argv[++i]);
    else return false;
  }
  return o.trials > 0;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool within(const PoseError& e) { return e.centre_mm <= kRightMm && e.rotation_deg <= kRightDeg; }

/// How far a match's unrefined pose can be from the truth when its template is the nearest one:
/// the rotation, the largest angle from a view of the range to its nearest template's (sampled
/// over `samples` random views, the image-position turn taken out); the centre, half a distance
/// step at the farthest distance plus half a diagonal of the match's position grid (T pixels at
/// the matching resolution) there. A match within both is "near".
struct GridReach {
  double rotation_deg = 0;
  double centre_mm = 0;
};

double rotation_angle_deg(const Mat33& a, const Mat33& b) {
  double trace = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) trace += static_cast<double>(a.m[k][i]) * static_cast<double>(b.m[k][i]);
  return std::acos(std::fmax(-1.0, std::fmin(1.0, (trace - 1) / 2))) * 180 / M_PI;
}

GridReach grid_reach(const TemplateSet& set, const EdgeModel& model, const ViewRange& range, int t, int samples) {
  std::vector<Mat33> rotations;
  for (const Template& tp : set.templates) rotations.push_back(Se3::from_theta_u(Vec3{}, tp.theta_u).rotation());
  GridReach reach;
  for (int k = 0; k < samples; ++k) {
    const Se3 view = random_view(model, set.camera, range, 7919u * static_cast<uint32_t>(k) + 3u);
    // The turn that brought the centre off the optical axis, taken out (as pose_of_match puts it back).
    const Vec3 ray = normalized(view * set.extent.centre);
    const Vec3 axis{-ray.y, ray.x, real(0)};
    const double sine = static_cast<double>(norm(axis));
    const Mat33 turn = sine > 0 ? rotation_exp(real(std::atan2(sine, static_cast<double>(ray.z)) / sine) * axis)
                                : Mat33::identity();
    const Mat33 centred = turn.transpose() * view.rotation();
    double nearest = 360;
    for (const Mat33& r : rotations) nearest = std::fmin(nearest, rotation_angle_deg(r, centred));
    reach.rotation_deg = std::fmax(reach.rotation_deg, nearest);
  }
  const double far = static_cast<double>(range.distance_max);
  const double step = static_cast<double>(set.params.downscale) * t / static_cast<double>(set.camera.px);
  const double half_step = std::sqrt(static_cast<double>(range.distance_ratio)) - 1;
  reach.centre_mm = 1000 * far * (half_step + std::sqrt(2.0) / 2 * step);
  return reach;
}

/// Where a trial that is not right fails, first cause first.
enum class Failure {
  kNone,          ///< right
  kNoNearMatch,   ///< no template match near the truth
  kScreenedOut,   ///< a near match, but not among the ones refined in full
  kConverged,     ///< a near match refined, but no refined pose within 2 mm and 2 degrees
  kScoreChose,    ///< a refined pose right, another one won
  kThreshold,     ///< the winner right, but refused by the acceptance rule
  kBudget         ///< not right, and the work budget ended the search (Detection::cut_short)
};
constexpr int kFailures = 7;
const char* failure_key(Failure f) {
  static const char* const kKeys[kFailures] = {"none", "no_near_match", "screened_out", "converged_elsewhere",
                                               "score_chose_wrong", "threshold_refused", "budget_ran_out"};
  return kKeys[static_cast<int>(f)];
}

Failure classify(const Detector& detector, const Detection& d, const Se3& truth, const Vec3& centre,
                 const std::vector<Mat33>& symmetries, const GridReach& reach) {
  const int t = detector.params().spread;
  auto match_near = [&](const TemplateMatch& m) {
    const PoseError e = pose_error(pose_of_match(detector.templates(), m, t), truth, centre, symmetries);
    return e.centre_mm <= reach.centre_mm && e.rotation_deg <= reach.rotation_deg;
  };
  bool any_near = false, refined_near = false, refined_right = false;
  for (const TemplateMatch& m : detector.matches()) any_near = any_near || match_near(m);
  for (const RefinedCandidate& c : d.refined) {
    refined_near = refined_near || match_near(c.match);
    refined_right = refined_right || within(pose_error(c.camera_from_model, truth, centre, symmetries));
  }
  const bool winner_right = within(pose_error(d.camera_from_model, truth, centre, symmetries));
  if (d.found && winner_right) return Failure::kNone;
  if (d.cut_short) return Failure::kBudget;
  if (winner_right) return Failure::kThreshold;
  if (refined_right) return Failure::kScoreChose;
  if (refined_near) return Failure::kConverged;
  if (any_near) return Failure::kScreenedOut;
  return Failure::kNoNearMatch;
}

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

/// One line per refined candidate: its match and refined pose's errors and what judged it.
void print_candidates(const Detector& detector, const Detection& d, const Se3& truth, const Vec3& centre,
                      const std::vector<Mat33>& symmetries) {
  for (const RefinedCandidate& c : d.refined) {
    const PoseError refined = pose_error(c.camera_from_model, truth, centre, symmetries);
    const PoseError matched =
        pose_error(pose_of_match(detector.templates(), c.match, detector.params().spread), truth, centre, symmetries);
    std::printf("  candidate: template %d share %.2f, match %.1f mm %.1f deg; refined %s kept %d of %d support %.2f "
                "scale %.2f px, %.2f mm %.2f deg\n",
                c.match.template_index, static_cast<double>(c.match.share), matched.centre_mm, matched.rotation_deg,
                status_name(c.status), c.kept, c.visible, static_cast<double>(c.support),
                static_cast<double>(c.residual_scale), refined.centre_mm, refined.rotation_deg);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr, "usage: bench_detection cube|wood_toy TRIALS [--no-object] [--from-truth] [--diagnose] "
                         "[--subdivisions N] [--in-plane N] [--distance-ratio R] [--seed S] [--max-points N] "
                         "[--quiet]\n");
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
  DetectorParams dp;
  if (o.max_points >= 0) dp.max_points_searched = o.max_points;
  Result<Detector> detector =
      Detector::create(model.value(), camera, std::move(templates).value(), dp, TrackerParams{});
  Result<Tracker> tracker = Tracker::create(model.value(), camera, random_view(model.value(), camera, o.templates.views, 1),
                                            TrackerParams{});
  if (!detector.ok() || !tracker.ok()) {
    std::fprintf(stderr, "%s\n", (detector.ok() ? tracker.error() : detector.error()).text().c_str());
    return 1;
  }
  const std::vector<Mat33> symmetries = o.scene == Scene::kCube ? cube_symmetries() : std::vector<Mat33>{Mat33::identity()};
  int found = 0, right = 0, refined = 0, truth_kept = 0, refined_kept = 0, cut_short = 0, wrong_far = 0;
  long long points = 0;
  int failures[kFailures] = {0};
  GridReach reach;
  if (o.diagnose && o.with_object)
    reach = grid_reach(detector.value().templates(), model.value(), o.templates.views, dp.spread, 500);
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
    cut_short += d.cut_short;
    wrong_far += d.found && o.with_object && (e.centre_mm > kFarMm || e.rotation_deg > kFarDeg);
    refined += static_cast<int>(d.refined.size());
    points += d.points_searched;
    const Failure failure =
        o.diagnose && o.with_object ? classify(detector.value(), d, truth, extent.centre, symmetries, reach)
                                    : Failure::kNone;
    ++failures[static_cast<int>(failure)];
    if (o.from_truth && o.with_object)
      truth_kept += within(tracked_from_truth(tracker.value(), frame.pixels.data(), frame.width, frame.height, truth,
                                              extent.centre, symmetries));
    if (o.from_truth && o.with_object) {
      const FrameView view = packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565);
      refined_kept += within(pose_error(detector.value().refine_from(view, truth).value().camera_from_model, truth,
                                        extent.centre, symmetries));
    }
    if (!o.quiet && o.diagnose) print_candidates(detector.value(), d, truth, extent.centre, symmetries);
    if (!o.quiet)
      std::printf("trial %d (%.0f mm): found %d right %d score %.2f match %.2f candidates %zu error %.2f mm %.2f deg "
                  "%.1f ms %d points %s\n",
                  k, 1000 * static_cast<double>((truth * extent.centre).z), d.found, ok, static_cast<double>(d.score),
                  static_cast<double>(d.match_share), d.refined.size(), e.centre_mm, e.rotation_deg, ms,
                  d.points_searched, failure_key(failure));
  }
  std::printf("detection: scene=%s object=%d trials=%d found=%d right=%d rate_percent=%.1f wrong=%d truth_kept=%d "
              "refined_kept=%d templates=%zu template_bytes=%zu make_ms=%.0f mean_ms=%.2f worst_ms=%.2f cpu_ms=%.2f "
              "refined_per_trial=%.1f points_per_trial=%.0f real=%s budget=%d cut_short=%d wrong_far=%d",
              o.scene == Scene::kCube ? "cube" : "wood_toy", o.with_object, o.trials, found, right,
              100.0 * right / o.trials, found - right, o.from_truth ? truth_kept : -1, o.from_truth ? refined_kept : -1, template_count, bytes, make_ms,
              total_ms / o.trials, worst_ms, cpu_ms / o.trials, static_cast<double>(refined) / o.trials,
              static_cast<double>(points) / o.trials, real_name(), dp.max_points_searched, cut_short, wrong_far);
  if (o.diagnose) {
    std::printf(" reach_deg=%.1f reach_mm=%.1f", reach.rotation_deg, reach.centre_mm);
    for (int f = 1; f < kFailures; ++f) std::printf(" %s=%d", failure_key(static_cast<Failure>(f)), failures[f]);
  }
  std::printf("\n");
  return 0;
}
