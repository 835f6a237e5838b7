// SPDX-License-Identifier: BSD-3-Clause
/// The status bounds learned from the scene (status_statistics.h): an approximate model's well
/// held frames (castel's 3-5 px residual scale, 1.5-2 px pose uncertainty) are tracked once
/// learned, a frame departing from what was learned is uncertain, residuals at chance stay
/// lost, a perfect model's scene keeps the fixed bounds, and a detected start learns nothing
/// until a frame tracked by the fixed bounds confirms it; the image's support of the outline
/// (edge_support.h): a track's frame supported only at chance is lost, and a detection is
/// confirmed only by a frame whose outline the image supports over confirm_support_share.
#include "edgetrack/status_statistics.h"
#include "edgetrack/tracking_status.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

constexpr int kMinPoints = 6;

/// A frame of 400 visible points, 360 matched and kept, range 8 px, nine tenths of the outline
/// supported by the image.
FrameMeasures frame(double scale_px, double uncertainty_px) {
  FrameMeasures m;
  m.visible = 400;
  m.matched = m.kept = 360;
  m.solved = true;
  m.matched_share = real(0.9);
  m.inlier_share = real(1);
  m.residual_scale = real(scale_px);
  m.pose_uncertainty_px = real(uncertainty_px);
  m.range = 8;
  m.support_share = real(0.9);
  return m;
}

/// Judges `m` by what `learned` has learned and lets it learn from the result, as the tracker does.
FrameStatus track(StatusStatistics& learned, const FrameMeasures& m, const StatusParams& params) {
  const FrameStatus status = judge_frame(m, params, kMinPoints, learned.bounds(params));
  learned.add(m, status.status, params);
  return status;
}

void test_running_statistic() {
  RunningStatistic s;
  s.add(real(2), real(0.1));
  s.add(real(4), real(0.1));
  TEST_NEAR("the first samples average plainly", s.mean(), 3.0, 1e-4);
  TEST_NEAR("the deviation is each sample's from the mean before it", s.deviation(), 1.0, 1e-4);
  for (int k = 0; k < 100; ++k) s.add(real(10), real(0.1));
  TEST_NEAR("then the mean follows the scene", s.mean(), 10.0, 1e-3);
  TEST("and the deviation settles", s.deviation() < real(0.01), true);
  s.clear();
  TEST("clear forgets", s.count(), 0);
}

}  // namespace

static void test_status_statistics() {
  test_running_statistic();
  const StatusParams params;
  // castel's frames as shipped: every one uncertain by the fixed bounds.
  TEST("by the fixed bounds an approximate model's frame is uncertain",
       judge_frame(frame(4.0, 1.8), params, kMinPoints).status, TrackingStatus::kUncertain);
  StatusStatistics learned;
  learned.restart(true);
  const double scales[] = {4.3, 4.0, 4.3, 3.9, 4.1, 3.8, 4.2, 3.9, 3.6, 3.5};
  int tracked = 0;
  for (double scale : scales) tracked += track(learned, frame(scale, scale / 2.2), params).status == TrackingStatus::kTracked;
  TEST("after a given start, such frames are tracked", tracked, 10);
  TEST("and the statistics have learned", learned.phase() == StatusStatistics::Phase::kLearned, true);
  const StatusBounds bounds = learned.bounds(params);
  TEST("the learned scale bound rose above the fixed one", bounds.tracked_scale_px > real(4.3), true);
  TEST("a frame at chance over the range is still lost", track(learned, frame(4.9, 2.0), params).status,
       TrackingStatus::kLost);
  FrameMeasures chance = frame(0.8, 0.5);
  chance.support_share = real(0.3);  // under 30 / 90: gradient orientations at chance
  TEST("a tight frame whose outline the image supports only at chance is lost",
       judge_frame(chance, params, kMinPoints, learned.bounds(params)).reason, StatusReason::kUnsupported);
  chance.support_share = real(0.4);
  TEST("one supported over chance is not", judge_frame(chance, params, kMinPoints, learned.bounds(params)).status,
       TrackingStatus::kTracked);
  chance = frame(3.8, 1.7);
  chance.support_share = real(0.2);
  TEST("a loose fit's support (the model beside the image's edges) is not judged",
       judge_frame(chance, params, kMinPoints, learned.bounds(params)).status, TrackingStatus::kTracked);
  FrameMeasures few = frame(3.8, 1.7);
  few.kept = 80;
  few.matched_share = real(0.2);
  TEST("a frame resting on a fifth of the model is uncertain", track(learned, few, params).status,
       TrackingStatus::kUncertain);

  // A scene the model fits at 2 px, searched over 16 px: 4.5 px is far from chance there, but
  // far from what the scene's tracked frames look like.
  StatusStatistics calm;
  calm.restart(true);
  for (int k = 0; k < 8; ++k) {
    FrameMeasures m = frame(k % 2 ? 2.1 : 1.9, 0.9);
    m.range = 16;
    track(calm, m, params);
  }
  FrameMeasures departing = frame(4.5, 0.9);
  departing.range = 16;
  TEST("a frame departing from the learned scale is uncertain",
       judge_frame(departing, params, kMinPoints, calm.bounds(params)).reason, StatusReason::kLooseFit);
  departing = frame(2.0, 3.0);
  departing.range = 16;
  TEST("and one departing from the learned pose uncertainty",
       judge_frame(departing, params, kMinPoints, calm.bounds(params)).reason, StatusReason::kPoseUnconstrained);

  // A perfect model's scene: the learned bounds are never tighter than the fixed ones.
  StatusStatistics perfect;
  perfect.restart(true);
  for (int k = 0; k < 20; ++k) track(perfect, frame(0.3, 0.1), params);
  const StatusBounds tight = perfect.bounds(params);
  const StatusBounds fixed = fixed_bounds(params);
  TEST("a perfect model's scene keeps the fixed bounds",
       tight.tracked_scale_px == fixed.tracked_scale_px && tight.max_pose_uncertainty_px == fixed.max_pose_uncertainty_px &&
           tight.min_matched_share == fixed.min_matched_share && tight.min_inlier_share == fixed.min_inlier_share,
       true);

  // A detection: the fixed bounds until a frame tracked by them confirms it.
  StatusStatistics detected;
  detected.restart(false);
  track(detected, frame(0.8, 0.5), params);
  TEST("the frame a detection was found on does not confirm it",
       detected.phase() == StatusStatistics::Phase::kUnconfirmed, true);
  for (int k = 0; k < 10; ++k)
    TEST("an unconfirmed detection keeps the fixed bounds", track(detected, frame(4.0, 1.8), params).status,
         TrackingStatus::kUncertain);
  TEST("and learns nothing from its uncertain frames", detected.residual_scale().count(), 0);
  // A wrong detection explains its matches (a tight fit) but the image supports only part of
  // its outline, the rest lying over flat image or clutter beside the object.
  FrameMeasures beside = frame(0.4, 0.5);
  beside.support_share = real(0.6);
  TEST("a detection whose outline the image supports on 0.6 is refuted", track(detected, beside, params).reason,
       StatusReason::kUnsupported);
  TEST("and stays unconfirmed", detected.phase() == StatusStatistics::Phase::kUnconfirmed, true);
  track(detected, frame(0.8, 0.5), params);
  TEST("a tracked frame confirms it", detected.phase() == StatusStatistics::Phase::kLearning, true);
  TEST("then a frame supported on 0.6 is tracked", track(detected, beside, params).status, TrackingStatus::kTracked);

  StatusParams fixed_only = params;
  fixed_only.learn_frames = 0;
  StatusStatistics off;
  off.restart(true);
  for (int k = 0; k < 10; ++k)
    TEST("learn_frames 0 keeps the fixed bounds", track(off, frame(4.0, 1.8), fixed_only).status,
         TrackingStatus::kUncertain);
  // The detector's candidates (learn_frames 0) are judged on the way to their pose.
  beside.support_share = real(0.1);
  TEST("learn_frames 0 has no support rule", track(off, beside, fixed_only).status, TrackingStatus::kTracked);

  StatusParams bad = params;
  bad.learning_rate = real(0);
  TEST("a learning rate of 0 is refused", check_status_params(bad).empty(), false);
  bad = params;
  bad.least_matched_share = real(0.6);
  TEST("a least matched share above the fixed one is refused", check_status_params(bad).empty(), false);
  bad = params;
  bad.support_angle_deg = real(90);
  TEST("a support angle of 90 degrees (every orientation) is refused", check_status_params(bad).empty(), false);
  bad = params;
  bad.confirm_support_share = real(1.5);
  TEST("a confirming support share over 1 is refused", check_status_params(bad).empty(), false);
  bad = params;
  bad.learn_frames = -1;
  TEST("negative learning frames are refused", check_status_params(bad).empty(), false);
}

TESTMAIN(test_status_statistics)
