// SPDX-License-Identifier: BSD-3-Clause
/// The tracker on generated QVGA sequences (the paper's set-up): from the true first pose it
/// follows the 60 mm cube within 1 mm with about 60 control points per frame and the
/// self-occluding wood toy within 2 mm (mean camera position error), the cube with a cylinder
/// beside it and a circle on the cylinder's end within 1 mm (both silhouettes and the circle
/// matched in every frame), reports no frame lost, never samples a hidden edge, and each `real`
/// stays near the double run stored in tests/tracker/golden (S40.23 within 0.1 mm in every frame),
/// with the default single edge hypothesis and, cube and toy, with three.
#include <cmath>
#include <cstdio>
#include <string>

#include "edgetrack/model_io.h"
#include "golden.h"
#include "golden_check.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

void report(const SequenceRun& run) {
  int matched = 0, outliers = 0;
  for (const FrameResult& f : run.frames) matched += f.points_matched;
  outliers = run.outliers;
  std::printf("%s: mean error %.3f mm, %.1f control points and %.1f matches per frame, %d outliers\n", real_name(),
              run.mean_position_error_mm, run.mean_points_sampled, double(matched) / run.frames.size(), outliers);
}

/// The tracker with three edge hypotheses per control point against its own golden file.
void compare_multiple_hypotheses_with_golden(Scene scene) {
  TrackerParams multiple;
  multiple.hypotheses = kMultipleHypotheses;
  const SequenceRun run = run_sequence(scene, kGoldenFrames, false, multiple);
  TEST("the multiple-hypothesis run runs", run.loaded, true);
  if (run.loaded) compare_with_golden(golden_name(scene, 1, kMultipleHypotheses), run);
}

}  // namespace

static void test_tracking_cube() {
  const SequenceRun run = run_sequence(Scene::kCube, kGoldenFrames, false);
  TEST("the cube sequence runs", run.loaded, true);
  if (!run.loaded) return;
  report(run);
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  const double motion = largest_vertex_motion(model.value(), qvga_camera(), run.truth);
  std::printf("largest image motion of a vertex: %.2f pixels per frame\n", motion);
  TEST("the camera moves smoothly, up to 3 pixels per frame", motion > 2.0 && motion <= 3.0, true);
  int unsolved = 0;
  for (const FrameResult& f : run.frames) unsolved += !f.pose.solved;
  std::printf("frames where LM reported a failure: %d\n", unsolved);
  if (std::string(real_name()) == "s47_16")  // the paper's finding: S47.16 minimises worse
    TEST("S47.16: LM fails in at most 10 % of the frames", unsolved <= 6, true);
  else
    TEST_EQUAL("every frame's pose is solved", unsolved, 0);
  TEST("about 60 control points per frame, as the paper (9 visible edges of about 65 pixels)",
       run.mean_points_sampled >= 50 && run.mean_points_sampled <= 70, true);
  TEST_NEAR("mean camera position error on the cube is below 1 mm", run.mean_position_error_mm, 0, 1.0);
  TEST_EQUAL("no frame is reported lost", count_status(run, TrackingStatus::kLost), 0);
  compare_with_golden(golden_name(Scene::kCube), run);
  compare_multiple_hypotheses_with_golden(Scene::kCube);
}

static void test_tracking_wood_toy() {
  const SequenceRun run = run_sequence(Scene::kWoodToy, kGoldenFrames, true);
  TEST("the wood toy sequence runs", run.loaded, true);
  if (!run.loaded) return;
  report(run);
  std::printf("hidden candidates dropped by Edge-ID (every 4th frame): %d\n", run.hidden_points_dropped);
  TEST("the toy hides some of its own edges in this sequence", run.hidden_points_dropped > 50, true);
  TEST_EQUAL("no control point hidden by more than a pixel is sampled", run.hidden_points_sampled, 0);
  TEST_NEAR("mean camera position error on the wood toy is below 2 mm", run.mean_position_error_mm, 0, 2.0);
  TEST_EQUAL("no frame is reported lost", count_status(run, TrackingStatus::kLost), 0);
  compare_with_golden(golden_name(Scene::kWoodToy), run);
  compare_multiple_hypotheses_with_golden(Scene::kWoodToy);
}

/// Cylinder silhouettes and a circle tracked with the cube: every frame solved, silhouette and
/// circle points matched in every frame, the cylinder hides part of the cube in some frames.
static void test_tracking_cube_cylinder() {
  const SequenceRun run = run_sequence(Scene::kCubeCylinder, kGoldenFrames, true);
  TEST("the cube and cylinder sequence runs", run.loaded, true);
  if (!run.loaded) return;
  report(run);
  const Result<EdgeModel> model = load_model(model_path(Scene::kCubeCylinder));
  const int first_curved = static_cast<int>(model.value().edges.size());
  const int circle = circle_primitive(model.value(), 0);
  int unsolved = 0, frames_with_both_silhouettes = 0, frames_with_circle = 0;
  for (const FrameResult& f : run.frames) unsolved += !f.pose.solved;
  for (const std::vector<int>& counts : run.matched_per_primitive) {
    frames_with_both_silhouettes += counts[first_curved] >= 3 && counts[first_curved + 1] >= 3;
    frames_with_circle += counts[circle] >= 5;
  }
  std::printf("frames with both silhouettes matched: %d, with the circle matched: %d\n", frames_with_both_silhouettes,
              frames_with_circle);
  std::printf("hidden candidates dropped by Edge-ID (every 4th frame): %d\n", run.hidden_points_dropped);
  if (std::string(real_name()) == "s47_16")
    TEST("S47.16: LM fails in at most 10 % of the frames", unsolved <= 6, true);
  else
    TEST_EQUAL("every frame's pose is solved", unsolved, 0);
  TEST_EQUAL("both cylinder silhouettes are matched in every frame", frames_with_both_silhouettes, kGoldenFrames);
  TEST_EQUAL("the circle is matched in every frame", frames_with_circle, kGoldenFrames);
  TEST_EQUAL("no control point hidden by more than a pixel is sampled", run.hidden_points_sampled, 0);
  TEST_NEAR("mean camera position error with the cylinder and circle is below 1 mm", run.mean_position_error_mm, 0,
            1.0);
  if (std::string(real_name()) != "s47_16")
    TEST_EQUAL("no frame is reported lost", count_status(run, TrackingStatus::kLost), 0);
  compare_with_golden(golden_name(Scene::kCubeCylinder), run);
}

TESTMAIN(test_tracking_cube)
TESTMAIN(test_tracking_wood_toy)
TESTMAIN(test_tracking_cube_cylinder)
