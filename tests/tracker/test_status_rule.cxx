// SPDX-License-Identifier: BSD-3-Clause
/// The status rule on hand-made measures: each reason is named by the case it stands for, the
/// chance threshold follows the searched range with its floor, a correction the matches
/// support is no reason, the pose uncertainty is uncertain past a pixel and lost past the range,
/// after a lost frame an uncertain one stays lost, and the settings' check refuses bad ones.
#include <string>

#include "edgetrack/pose_uncertainty.h"
#include "edgetrack/tracker_params.h"
#include "edgetrack/tracking_status.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// A well tracked frame: 60 visible points, 58 matched, 55 kept, 0.4 px scale, range 4.
FrameMeasures tracked_frame() {
  FrameMeasures m;
  m.visible = 60;
  m.matched = 58;
  m.kept = 55;
  m.solved = true;
  m.matched_share = real(55.0 / 60.0);
  m.inlier_share = real(55.0 / 58.0);
  m.residual_scale = real(0.4);
  m.correction_px = real(1.5);
  m.range = 4;
  return m;
}

bool is(const FrameStatus& s, TrackingStatus status, StatusReason reason) {
  return s.status == status && s.reason == reason;
}

}  // namespace

static void test_status_rule() {
  const StatusParams params;
  const int min_points = 6;
  FrameMeasures m = tracked_frame();
  TEST("a well fitted frame is tracked", is(judge_frame(m, params, min_points), TrackingStatus::kTracked, StatusReason::kNone), true);

  m = tracked_frame();
  m.visible = 5;
  TEST("too few visible points: lost", is(judge_frame(m, params, min_points), TrackingStatus::kLost, StatusReason::kTooFewVisible), true);
  m = tracked_frame();
  m.solved = false;
  TEST("an unsolved pose: lost", is(judge_frame(m, params, min_points), TrackingStatus::kLost, StatusReason::kPoseFailed), true);

  // Chance level: matches spread evenly over +-4 px give a scale of about 0.74 * 4 = 3 px.
  m = tracked_frame();
  m.residual_scale = real(3.0);
  TEST("a scale at chance over the range: lost",
       is(judge_frame(m, params, min_points), TrackingStatus::kLost, StatusReason::kChanceResiduals), true);
  m.range = 8;
  TEST("the same scale over twice the range is not chance (uncertain: loose fit)",
       is(judge_frame(m, params, min_points), TrackingStatus::kUncertain, StatusReason::kLooseFit), true);
  m.range = 2;
  m.residual_scale = real(1.4);
  TEST("a small range keeps the floor: 1.4 px over a 2 px range is not chance",
       judge_frame(m, params, min_points).status, TrackingStatus::kUncertain);
  m.residual_scale = real(1.6);
  TEST("1.6 px over a 2 px range is", judge_frame(m, params, min_points).status, TrackingStatus::kLost);

  m = tracked_frame();
  m.kept = 25;
  m.matched_share = real(25.0 / 60.0);
  TEST("under half the visible points kept: uncertain",
       is(judge_frame(m, params, min_points), TrackingStatus::kUncertain, StatusReason::kFewMatched), true);
  m = tracked_frame();
  m.visible = 12;
  m.matched = 11;
  m.kept = 11;
  m.matched_share = real(11.0 / 12.0);
  m.inlier_share = real(1);
  TEST("11 matches fitting well: too few to tell a fit from chance, uncertain",
       is(judge_frame(m, params, min_points), TrackingStatus::kUncertain, StatusReason::kFewToCheck), true);
  m.after_loss = true;
  TEST("and after a loss, lost", judge_frame(m, params, min_points).status, TrackingStatus::kLost);
  m = tracked_frame();
  m.kept = 12;
  m.visible = m.matched = 12;
  m.matched_share = m.inlier_share = real(1);
  TEST("12 are enough", judge_frame(m, params, min_points).status, TrackingStatus::kTracked);
  m = tracked_frame();
  m.inlier_share = real(0.45);
  TEST("half the matches outliers: uncertain",
       is(judge_frame(m, params, min_points), TrackingStatus::kUncertain, StatusReason::kManyOutliers), true);
  m = tracked_frame();
  m.correction_px = real(9);
  TEST("a correction beyond the range that the matches support: tracked",
       judge_frame(m, params, min_points).status, TrackingStatus::kTracked);
  m = tracked_frame();
  m.pose_uncertainty_px = real(1.5);
  TEST("a pose uncertainty over a pixel: uncertain",
       is(judge_frame(m, params, min_points), TrackingStatus::kUncertain, StatusReason::kPoseUnconstrained), true);
  m.pose_uncertainty_px = real(4.5);
  TEST("beyond the range searched: lost",
       is(judge_frame(m, params, min_points), TrackingStatus::kLost, StatusReason::kPoseUndetermined), true);
  m.range = 8;
  TEST("within a wider range: uncertain", judge_frame(m, params, min_points).status, TrackingStatus::kUncertain);
  m = tracked_frame();
  m.kept = m.matched = 8;
  m.inlier_share = real(1);
  m.matched_share = real(8.0 / 60.0);
  m.pose_uncertainty_px = real(kUnconstrainedPx);
  TEST("few matches that leave a direction free: lost, not only too few to check",
       is(judge_frame(m, params, min_points), TrackingStatus::kLost, StatusReason::kPoseUndetermined), true);
  m = tracked_frame();
  m.saturations = 1;
  TEST("a saturation: uncertain",
       is(judge_frame(m, params, min_points), TrackingStatus::kUncertain, StatusReason::kSaturated), true);

  m = tracked_frame();
  m.residual_scale = real(1.2);
  m.after_loss = true;
  TEST("after a loss, an uncertain frame stays lost",
       is(judge_frame(m, params, min_points), TrackingStatus::kLost, StatusReason::kNotReacquired), true);
  m.residual_scale = real(0.4);
  TEST("after a loss, a tracked frame is tracked", judge_frame(m, params, min_points).status, TrackingStatus::kTracked);
  TEST("the default settings pass their check", check_status_params(params).empty(), true);
  StatusParams bad = params;
  bad.lost_scale_floor_px = real(0.5);
  TEST("a chance floor below the tracked scale is refused", check_status_params(bad).empty(), false);
  bad = params;
  bad.min_inlier_share = real(1.5);
  TEST("a share above 1 is refused", check_status_params(bad).empty(), false);
  bad = params;
  bad.edge_location_px = real(-0.1);
  TEST("a negative edge location error is refused", check_status_params(bad).empty(), false);
  TrackerParams tracker_params;
  tracker_params.status.lost_uncertainty_range_share = real(0);
  TEST("and the tracker's settings check refuses them", check_tracker_params(tracker_params).has_value(), true);
  for (int r = 0; r < kStatusReasonCount; ++r)
    TEST("every reason has a name", std::string(reason_name(static_cast<StatusReason>(r))) != "?", true);
}

TESTMAIN(test_status_rule)
