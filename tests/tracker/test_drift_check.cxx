// SPDX-License-Identifier: BSD-3-Clause
/// The drift check (drift_check.h; issue #27, drift in clutter), switched on (it is off by
/// default, for its cost): the generated cube with dark lines 8 mm beside every edge, tracked from its true first pose, must
/// lose no frame and stay within 1.5 times the mean error of each frame solved alone from its true
/// pose (the target); without the check the same run walks onto the lines. Also the
/// overlay distance the check compares poses by, and its settings by name and in the XML.
#include <cstdio>
#include <string>

#include "edgetrack/drift_check.h"
#include "edgetrack/tracker_params.h"
#include "edgetrack/visp_config.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

static void test_overlay_distance() {
  EdgeModel model;
  model.vertices = {Vec3{real(0), real(0), real(0)}, Vec3{real(0.01), real(0), real(0)}};
  PinholeCamera camera;
  camera.px = camera.py = real(200);
  camera.u0 = real(160);
  camera.v0 = real(120);
  const Se3 at(Mat33::identity(), Vec3{real(0), real(0), real(0.2)});
  const Se3 moved(Mat33::identity(), Vec3{real(0.001), real(0), real(0.2)});  // 1 mm across at 200 mm: 1 px
  TEST_NEAR("the same pose parts by nothing", static_cast<double>(largest_overlay_distance_px(model, camera, at, at)),
            0.0, 1e-9);
  // S47.16 keeps a projection of about 160 px to some 2^-16 relative: its 1 px is within 0.01.
  TEST_NEAR("1 mm across at 200 mm is 1 px at px = 200",
            static_cast<double>(largest_overlay_distance_px(model, camera, at, moved)), 1.0, 1e-2);
  const Se3 behind(Mat33::identity(), Vec3{real(0), real(0), real(-0.2)});
  TEST_NEAR("points behind the camera are passed over",
            static_cast<double>(largest_overlay_distance_px(model, camera, at, behind)), 0.0, 1e-9);
}

static void test_drift_settings() {
  ThinLineParams p;
  TEST("the check is off by default", p.check == DriftAction::kNone, true);
  TEST("check=2 corrects", set_thin_line_param(p, "check", 2).empty() && p.check == DriftAction::kCorrect, true);
  TEST("check=1 reports", set_thin_line_param(p, "check", 1).empty() && p.check == DriftAction::kReport, true);
  TEST("check=3 is refused", set_thin_line_param(p, "check", 3).empty(), false);
  TEST("check_sigmas=4 is taken", set_thin_line_param(p, "check_sigmas", 4).empty(), true);
  TEST_NEAR("to its value", static_cast<double>(p.check_sigmas), 4.0, 1e-4);
  TEST("check_sigmas=0 is refused", set_thin_line_param(p, "check_sigmas", 0).empty(), false);
  TEST("check_share=0.3 is taken", set_thin_line_param(p, "check_share", 0.3).empty(), true);
  TEST("check_share=1.5 is refused", set_thin_line_param(p, "check_share", 1.5).empty(), false);
  TrackerConfig config;
  const Result<ConfigNotes> read = apply_visp_config_text(
      "<conf>\n<edgetrack><thin_lines><check>2</check></thin_lines></edgetrack>\n</conf>", "drift.xml", config);
  TEST("the XML block switches the check on", read.ok() && config.params.thin_lines.check == DriftAction::kCorrect, true);
  TrackerParams params;
  params.thin_lines.check_sigmas = real(-1);
  TEST("check_tracker_params refuses a negative check_sigmas", check_tracker_params(params).has_value(), true);
}

static void test_drift_in_clutter() {
  constexpr int kFrames = 24;
  SequenceSpec spec;
  spec.clutter = 0.008;
  TrackerParams unchecked, correcting;
  unchecked.thin_lines.check = DriftAction::kNone;
  correcting.thin_lines.check = DriftAction::kCorrect;
  const SequenceRun checked = run_sequence(Scene::kCube, kFrames, false, correcting, spec);
  const SequenceRun plain = run_sequence(Scene::kCube, kFrames, false, unchecked, spec);
  TEST("both runs load", checked.loaded && plain.loaded, true);
  if (!checked.loaded || !plain.loaded) return;
  // Each frame alone: its true pose as a one-frame sequence, solved from that pose by the pose
  // step alone (tracking_eval_clutter_dynamics' "alone").
  double alone = 0;
  for (int k = 0; k < kFrames; ++k) {
    SequenceSpec one = spec;
    one.poses = {checked.truth[static_cast<size_t>(k)]};
    const SequenceRun single = run_sequence(Scene::kCube, 1, false, unchecked, one);
    if (!single.loaded) return;
    alone += single.position_error_mm[0] / kFrames;
  }
  std::printf("%s cube, lines 8 mm beside the edges, %d frames: with the check mean %.3f mm, without the check "
              "%.3f mm, each frame alone %.3f mm\n",
              real_name(), kFrames, checked.mean_position_error_mm, plain.mean_position_error_mm, alone);
  TEST_EQUAL("with the check no frame is lost", count_status(checked, TrackingStatus::kLost), 0);
  TEST("with the check the mean error is at most 1.5 times alone's",
       checked.mean_position_error_mm <= 1.5 * alone, true);
  TEST("without the check the run drifts beyond it (the case is one of drift)",
       plain.mean_position_error_mm > 1.5 * alone, true);
}

static void test_drift_check() {
  test_overlay_distance();
  test_drift_settings();
  test_drift_in_clutter();
}

TESTMAIN(test_drift_check)
