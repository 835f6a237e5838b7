// SPDX-License-Identifier: BSD-3-Clause
/// The generated cube and wood toy played forwards and then backwards (scene_extras.h's
/// there_and_back), as the long reliability run does (docs/results/reliability.md): the cube at
/// the paper's speed and four times faster, and both models five times faster (13-14 px per QVGA
/// frame), where the motion reverses at once by twice that from one frame to the next. No frame
/// is lost and the mean camera position error stays under 0.5 mm, the turn included: the
/// prediction overshoots there by a frame's motion, and the frame is tracked again from the last
/// trusted pose at rest (MotionParams::retry_from_trusted; without it the toy is lost from the
/// turn on). At five times the speed each `real`
/// stays near the double run (S40.23 within 0.1 mm in every frame).
#include <cstdio>
#include <string>
#include <vector>

#include "edgetrack/scene_extras.h"
#include "golden.h"
#include "golden_check.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

SequenceRun run_there_and_back(Scene scene, const std::string& label, const SequenceSpec& spec) {
  const SequenceRun run = run_sequence(scene, static_cast<int>(spec.poses.size()), false, TrackerParams{}, spec);
  TEST((label + ": the sequence runs").c_str(), run.loaded, true);
  if (!run.loaded) return run;
  int retried = 0;
  for (const FrameResult& f : run.frames) retried += f.retried;
  std::printf("%s %s: %zu frames, mean error %.3f mm, %d uncertain, %d lost, %d retried\n", real_name(), label.c_str(),
              run.frames.size(), run.mean_position_error_mm, count_status(run, TrackingStatus::kUncertain),
              count_status(run, TrackingStatus::kLost), retried);
  TEST_EQUAL((label + ": no frame is lost").c_str(), count_status(run, TrackingStatus::kLost), 0);
  TEST_NEAR((label + ": mean camera position error below 0.5 mm").c_str(), run.mean_position_error_mm, 0, 0.5);
  return run;
}

void check_slower(int speed) {
  SequenceSpec spec;
  spec.poses = there_and_back(true_poses(Scene::kCube, speed > 1 ? 40 : 60, speed));
  run_there_and_back(Scene::kCube, "cube, " + std::to_string(speed) + " times the paper's speed", spec);
}

/// At the turn the prediction is a frame's motion beyond the last trusted pose and the object a
/// frame's motion before it: the retry tracks it, and the prediction follows the new direction.
void check_reversal(Scene scene, const char* name) {
  const std::string label = std::string(name) + ", 5 times the paper's speed";
  const SequenceRun run = run_there_and_back(scene, label, reversal_spec(scene));
  if (!run.loaded) return;
  const FrameResult& turn = run.frames[kReversalTurn + 1];
  std::printf("  the frame after the turn: %s, %s, range %u px, error %.3f mm\n", status_name(turn.status),
              turn.retried ? "retried" : "not retried", turn.measures.range,
              run.position_error_mm[kReversalTurn + 1]);
  TEST("the frame after the turn is tracked", turn.status == TrackingStatus::kTracked, true);
  TEST_NEAR("within 1 mm of the truth", run.position_error_mm[kReversalTurn + 1], 0, 1.0);
  compare_with_golden(reversal_golden_name(scene), run);
}

/// The toy's turn is one the prediction alone cannot follow: without the retry the frame after
/// the turn fits loosely 20 mm off, and frames after it are lost (how many depends on the
/// `real`: a frame that fits well after a loss is found again, whatever its correction).
void check_turn_needs_the_retry() {
  const SequenceSpec spec = reversal_spec(Scene::kWoodToy);
  TrackerParams without;
  without.motion.retry_from_trusted = false;
  const SequenceRun run = run_sequence(Scene::kWoodToy, static_cast<int>(spec.poses.size()), false, without, spec);
  TEST("the toy's reversal runs without the retry", run.loaded, true);
  if (!run.loaded) return;
  const int lost = count_status(run, TrackingStatus::kLost);
  std::printf("%s wood toy there and back without the retry: %d lost, the turn %s\n", real_name(), lost,
              status_name(run.frames[kReversalTurn + 1].status));
  TEST("without the retry the frame after the turn is not tracked",
       run.frames[kReversalTurn + 1].status != TrackingStatus::kTracked, true);
  TEST("and frames after it are lost", lost > 0, true);
}

}  // namespace

static void test_back_and_forth() {
  check_slower(1);
  check_slower(4);
  check_reversal(Scene::kCube, "cube");
  check_reversal(Scene::kWoodToy, "wood toy");
  check_turn_needs_the_retry();
}

TESTMAIN(test_back_and_forth)
