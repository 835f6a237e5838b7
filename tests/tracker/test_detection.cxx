// SPDX-License-Identifier: BSD-3-Clause
/// Detection on generated QVGA frames, from the model alone: the cube and the wood toy at random
/// poses inside a small template range (a 25-degree cone of views, 140-170 mm), over a textured
/// background with distractor lines, are found within 2 mm and 2 degrees of the truth (for the
/// cube, of any of its 24 symmetric poses) at the rate the evaluation measures (about 80 % for
/// the cube and the wood toy: docs/results/detection.md), where a build's rounding moves a
/// single trial across the 2 mm / 2 degree line: at least 2 of 4 trials of the cube (S47.16
/// finds 2, the others 3) and 3 of 4 of the wood toy; no two
/// of a frame's template matches stand for the same pose (the suppression before screening);
/// frames with the background and the lines but no object are "not found", every one; on a
/// frame whose candidates all settle a few degrees off, acceptable but not within a quarter
/// pixel, the tilted restarts run and find the pose.
#include <cstdio>
#include <vector>

#include "detection_scene.h"
#include "edgetrack/detector/detector.h"
#include "edgetrack/model_io.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kTrials = 4;
constexpr int kLines = 12;

TemplateParams small_range(const Vec3& axis) {
  TemplateParams params;
  params.views.axis = axis;
  params.views.max_angle = real(25.0 * 3.141592653589793 / 180);
  params.views.subdivisions = 2;
  params.views.in_plane_steps = 18;
  params.views.distance_min = real(0.14);
  params.views.distance_max = real(0.17);
  return params;
}

/// The evaluation's range of views (bench_detection's): within 60 degrees of the model's z axis,
/// 120 to 200 mm.
ViewRange evaluation_views() {
  ViewRange views = small_range(Vec3{real(0), real(0), real(1)}).views;
  views.max_angle = real(60.0 * 3.141592653589793 / 180);
  views.distance_min = real(0.12);
  views.distance_max = real(0.2);
  return views;
}

/// The pairs of `detector`'s last matches within its suppression angle and distance of each other.
int unsuppressed_pairs(const Detector& detector) {
  const std::vector<TemplateMatch>& matches = detector.matches();
  const DetectorParams& p = detector.params();
  const ModelExtent& extent = detector.templates().extent;
  int pairs = 0;
  for (size_t i = 0; i < matches.size(); ++i)
    for (size_t j = i + 1; j < matches.size(); ++j) {
      const Se3 a = pose_of_match(detector.templates(), matches[i], p.spread);
      const Se3 b = pose_of_match(detector.templates(), matches[j], p.spread);
      const Vec3 turn = rotation_log(a.rotation().transpose() * b.rotation());
      const double angle = static_cast<double>(norm(turn)) * 180 / 3.141592653589793;
      const double apart = static_cast<double>(norm(a * extent.centre - b * extent.centre));
      pairs += angle < static_cast<double>(p.suppress_deg) - 0.01 &&
               apart < static_cast<double>(p.suppress_radii * extent.radius) - 1e-4;
    }
  return pairs;
}

void check_scene(Scene scene, const Vec3& axis, const std::vector<Mat33>& symmetries, int least_right) {
  const Result<EdgeModel> model = load_model(model_path(scene));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const TemplateParams params = small_range(axis);
  Result<TemplateSet> templates = make_template_set(model.value(), camera, params);
  TEST("templates are made", templates.ok(), true);
  if (!templates.ok()) return;
  const ModelExtent extent = templates.value().extent;
  std::printf("%s: %zu templates, %zu bytes\n", real_name(), templates.value().templates.size(),
              templates.value().memory_bytes());
  Result<Detector> detector =
      Detector::create(model.value(), camera, std::move(templates).value(), DetectorParams{}, TrackerParams{});
  TEST("the detector is made", detector.ok(), true);
  if (!detector.ok()) return;
  Rgb565Frame frame;
  int right = 0, false_found = 0, near_pairs = 0;
  for (int k = 0; k < kTrials; ++k) {
    const uint32_t seed = 11 + static_cast<uint32_t>(k);
    const Se3 truth = random_view(model.value(), camera, params.views, seed);
    render_trial(model.value(), camera, truth, true, kLines, seed, frame);
    const Detection d = detector.value()
                            .detect(packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565))
                            .value();
    const PoseError e = pose_error(d.camera_from_model, truth, extent.centre, symmetries);
    std::printf("  trial %d: found %d score %.2f error %.3f mm %.3f deg, %zu candidates refined\n", k, d.found,
                static_cast<double>(d.score), e.centre_mm, e.rotation_deg, d.refined.size());
    right += d.found && e.centre_mm <= 2 && e.rotation_deg <= 2;
    near_pairs += unsuppressed_pairs(detector.value());
    render_trial(model.value(), camera, truth, false, kLines, seed, frame);
    const Detection none =
        detector.value()
            .detect(packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565))
            .value();
    std::printf("  without the object: found %d score %.2f, %zu candidates refined\n", none.found,
                static_cast<double>(none.score), none.refined.size());
    false_found += none.found;
  }
  std::printf("%d of %d trials found within 2 mm and 2 degrees\n", right, kTrials);
  TEST("the trials are found within 2 mm and 2 degrees at the evaluation's rate", right >= least_right, true);
  TEST_EQUAL("no two template matches of a frame stand for the same pose", near_pairs, 0);
  TEST_EQUAL("no frame without the object is found", false_found, 0);
}

/// The detector's refinement alone from the true pose (Detector::refine_from) on frames of the
/// evaluation's range (views within 60 degrees, 120 to 200 mm: bench_detection's frames and
/// seeds) where a refinement whose guessed start takes each point's strongest edge with an
/// unweighted first solve, and that is not run again from its pose as a given one, settles
/// more than 2 mm or 2 degrees off (docs/results/detection.md, refined from truth): the
/// default schedule ends within 2 mm and 2 degrees on every one, and with a fit the detector
/// accepts on most.
void check_refinement_from_truth(Scene scene, const std::vector<Mat33>& symmetries, const std::vector<int>& trials) {
  const Result<EdgeModel> model = load_model(model_path(scene));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const ViewRange evaluation = evaluation_views();
  // The refinement reads the templates only for the camera and the model's extent: a small set.
  Result<TemplateSet> templates =
      make_template_set(model.value(), camera, small_range(Vec3{real(0), real(0), real(1)}));
  TEST("templates are made", templates.ok(), true);
  if (!templates.ok()) return;
  const ModelExtent extent = templates.value().extent;
  const DetectorParams params;
  Result<Detector> detector =
      Detector::create(model.value(), camera, std::move(templates).value(), params, TrackerParams{});
  TEST("the detector is made", detector.ok(), true);
  if (!detector.ok()) return;
  Rgb565Frame frame;
  int within = 0, accepted = 0;
  for (const int k : trials) {
    const uint32_t seed = 100003u + static_cast<uint32_t>(k);
    const Se3 truth = random_view(model.value(), camera, evaluation, seed);
    render_trial(model.value(), camera, truth, true, kLines, seed, frame);
    const RefinedCandidate c =
        detector.value()
            .refine_from(packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565), truth)
            .value();
    const PoseError e = pose_error(c.camera_from_model, truth, extent.centre, symmetries);
    std::printf("  trial %d: refined from the truth %s, scale %.2f px, %.3f mm %.3f deg\n", k, status_name(c.status),
                static_cast<double>(c.residual_scale), e.centre_mm, e.rotation_deg);
    within += e.centre_mm <= 2 && e.rotation_deg <= 2;
    accepted += c.status == TrackingStatus::kTracked && c.residual_scale <= params.max_residual_scale_px;
  }
  TEST_EQUAL("refined from the true pose, every trial ends within 2 mm and 2 degrees", within,
             static_cast<int>(trials.size()));
  TEST("and most with a tracked fit within the accepted residual scale", 2 * accepted > static_cast<int>(trials.size()),
       true);
}

/// The evaluation's cube frame 62 (bench_detection's frames and seed 1: views within 60 degrees,
/// 120 to 200 mm), detected with templates in a 25-degree cone about its own view: every
/// candidate refined from a match settles a few degrees off, most of them within the accepted
/// residual scale but none within a quarter pixel (confident). The best one refined again from its pose
/// tilted (DetectorParams::restart_tilt_deg) finds the pose, fitting within a quarter pixel (confident),
/// and that fit wins over the merely acceptable ones.
void check_restart_from_acceptable() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const ViewRange evaluation = evaluation_views();
  const uint32_t seed = 100003u + 62u;
  const Se3 truth = random_view(model.value(), camera, evaluation, seed);
  const ModelExtent extent = model_extent(model.value());
  // The camera's direction from the model's centre, in the model's frame: the cone's axis.
  const Vec3 axis = normalized(truth.inverse() * Vec3{} - extent.centre);
  Result<TemplateSet> templates = make_template_set(model.value(), camera, small_range(axis));
  TEST("templates are made", templates.ok(), true);
  if (!templates.ok()) return;
  DetectorParams params;
  // The first three matches only: this frame's fourth is, in some real builds (S47.16), confident
  // by itself, and then no restart runs; the claim here is about the restarts.
  params.refined_candidates = 3;
  // No work budget: it may end the search before the restarts (S47.16 spends more points on this
  // frame's candidates); what a budget cuts is test_detection_budget's claim.
  params.max_points_searched = 0;
  Result<Detector> detector =
      Detector::create(model.value(), camera, std::move(templates).value(), params, TrackerParams{});
  TEST("the detector is made", detector.ok(), true);
  if (!detector.ok()) return;
  Rgb565Frame frame;
  render_trial(model.value(), camera, truth, true, kLines, seed, frame);
  const Detection d = detector.value()
                          .detect(packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565))
                          .value();
  const PoseError e = pose_error(d.camera_from_model, truth, extent.centre, cube_symmetries());
  std::printf("found %d, %.3f mm %.3f deg, %zu candidates refined:\n", d.found, e.centre_mm, e.rotation_deg,
              d.refined.size());
  const auto acceptable = [&](const RefinedCandidate& c) {
    return c.status == TrackingStatus::kTracked && c.kept_share >= params.min_kept_share &&
           c.support >= params.min_support && c.residual_scale <= params.max_residual_scale_px;
  };
  const auto confident = [&](const RefinedCandidate& c) {
    return acceptable(c) && c.residual_scale <= params.confident_scale_px &&
           c.kept_share >= params.confident_kept_share;
  };
  // The restarts come last, all from one candidate's match (up to 4, ending at the first
  // confident one); the candidates before them are the matches' own.
  const int restarted_index = d.refined.back().match.template_index;
  size_t first_restart = d.refined.size();
  while (first_restart > 0 && d.refined[first_restart - 1].match.template_index == restarted_index) --first_restart;
  // When the candidate restarted from was the last one refined from the matches, it opens that run.
  bool seen_before = false;
  for (size_t k = 0; k < first_restart; ++k)
    seen_before = seen_before || d.refined[k].match.template_index == restarted_index;
  if (!seen_before) ++first_restart;
  int acceptable_before = 0, confident_before = 0, restarted_from = 0;
  for (size_t k = 0; k < d.refined.size(); ++k) {
    const RefinedCandidate& c = d.refined[k];
    std::printf("  template %d %s scale %.2f px\n", c.match.template_index, status_name(c.status),
                static_cast<double>(c.residual_scale));
    if (k >= first_restart) continue;
    acceptable_before += acceptable(c);
    confident_before += confident(c);
    restarted_from += c.match.template_index == restarted_index;
  }
  TEST("refined from the matches, some candidates are acceptable", acceptable_before > 0, true);
  TEST_EQUAL("and none is confident", confident_before, 0);
  TEST("the last candidates were refined again from one of them, from tilted starts",
       restarted_from == 1 && d.refined.size() - first_restart <= 4, true);
  TEST("a tilted start is confident", confident(d.refined.back()), true);
  TEST("and wins: the pose is found within 2 mm and 2 degrees", d.found && e.centre_mm <= 2 && e.rotation_deg <= 2,
       true);
}

}  // namespace

static void test_detection_restarts() { check_restart_from_acceptable(); }

static void test_detection_refine_from_truth() {
  check_refinement_from_truth(Scene::kCube, cube_symmetries(), {7, 25, 37, 43, 53, 60, 62, 77});
  check_refinement_from_truth(Scene::kWoodToy, {Mat33::identity()}, {1, 8, 20, 21, 22, 24, 60, 68});
}

static void test_detection_cube() {
  check_scene(Scene::kCube, normalized(Vec3{real(0.5), real(-0.6), real(1)}), cube_symmetries(), 2);
}

static void test_detection_wood_toy() {
  check_scene(Scene::kWoodToy, normalized(Vec3{real(-0.4), real(-0.7), real(1)}), {Mat33::identity()}, 3);
}

TESTMAIN(test_detection_cube)
TESTMAIN(test_detection_wood_toy)
TESTMAIN(test_detection_refine_from_truth)
TESTMAIN(test_detection_restarts)
