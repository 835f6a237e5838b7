// SPDX-License-Identifier: BSD-3-Clause
/// A rolling shutter (the rows read over a whole frame interval, top first) on the fast cube
/// sequence (every 5th pose, 13-15 px per QVGA frame): the bottom row sees the cube a frame's
/// motion after the top, a shear of up to 7 px either side of the middle row that no rigid pose
/// fits. Given the readout, the tracker sees each row at its own time (rolling_shutter.h): what
/// is left of the shear's cost is the constant-velocity model's error, which must stay under a
/// quarter of that cost over the same trajectory under a global shutter. Before a velocity is
/// measured (the first two frames) the readout changes nothing, bit for bit.
/// The drift check (drift_check.h, on by default) on the same frames, the readout given: the
/// scene has no thin dark line, so whatever matches the thin-line test masks and however often
/// the gate has the rest solved again, it must find no drift (reported, no frame is uncertain for
/// drift) and so leave every frame as the tracker without the check solves it, bit for bit.
#include <cstdio>

#include "golden.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kFrames = 10;
constexpr int kRenders = 16;  ///< renders a frame: rows from one at most 1 px of motion from their read time

SequenceRun run(double readout, double given, DriftAction check = ThinLineParams{}.check) {
  SequenceSpec spec;
  spec.subsample = kFastSpeedUp;
  spec.readout = readout;
  spec.readout_renders = kRenders;
  TrackerParams params;
  params.readout = real(given);
  params.thin_lines.check = check;
  return run_sequence(Scene::kCube, kFrames, false, params, spec);
}

double mean_from(const SequenceRun& run, int first) {
  double sum = 0;
  for (size_t k = static_cast<size_t>(first); k < run.position_error_mm.size(); ++k) sum += run.position_error_mm[k];
  return sum / static_cast<double>(run.position_error_mm.size() - static_cast<size_t>(first));
}

int count_reason(const SequenceRun& run, StatusReason reason) {
  int count = 0;
  for (const FrameResult& frame : run.frames) count += frame.reason == reason ? 1 : 0;
  return count;
}

bool same_frames(const SequenceRun& a, const SequenceRun& b) {
  if (a.frames.size() != b.frames.size()) return false;
  for (size_t k = 0; k < a.frames.size(); ++k)
    if (!same_bits(a.frames[k].camera_from_model, b.frames[k].camera_from_model) ||
        a.frames[k].status != b.frames[k].status)
      return false;
  return true;
}

}  // namespace

static void test_rolling_shutter_tracking_cube() {
  const SequenceRun global = run(0, 0);
  const SequenceRun ignored = run(1, 0);
  const SequenceRun given = run(1, 1);
  TEST("the sequences run", global.loaded && ignored.loaded && given.loaded, true);
  if (!global.loaded || !ignored.loaded || !given.loaded) return;
  // The velocity is measured from two trusted frames: frames 0 and 1 are tracked as before.
  const int measured = 2;
  std::printf("%s cube, %d frames read over a frame interval: mean camera position error from frame %d on %.3f mm with "
              "the readout given, %.3f mm without it, %.3f mm under a global shutter; lost %d, %d, %d\n",
              real_name(), kFrames, measured, mean_from(given, measured), mean_from(ignored, measured),
              mean_from(global, measured), count_status(given, TrackingStatus::kLost),
              count_status(ignored, TrackingStatus::kLost), count_status(global, TrackingStatus::kLost));
  TEST_EQUAL("with the readout given no frame is lost", count_status(given, TrackingStatus::kLost), 0);
  bool same_start = true;
  for (int k = 0; k < measured; ++k) same_start = same_start && same_bits(given.frames[k].camera_from_model,
                                                                               ignored.frames[k].camera_from_model);
  TEST("before a velocity is measured the readout changes nothing", same_start, true);
  const double shear_mm = mean_from(ignored, measured) - mean_from(global, measured);
  TEST("the shear costs the tracker that ignores it", shear_mm > 0.1, true);
  TEST("given the readout, the error is within a quarter of the shear of the global shutter's",
       mean_from(given, measured) <= mean_from(global, measured) + 0.25 * shear_mm, true);
}

static void test_rolling_shutter_drift_check_cube() {
  const SequenceRun off = run(1, 1, DriftAction::kNone);
  const SequenceRun reported = run(1, 1, DriftAction::kReport);
  const SequenceRun corrected = run(1, 1, DriftAction::kCorrect);
  TEST("the sequences run", off.loaded && reported.loaded && corrected.loaded, true);
  if (!off.loaded || !reported.loaded || !corrected.loaded) return;
  std::printf("%s cube, %d frames read over a frame interval, the readout given: mean camera position error %.3f mm "
              "with the drift check correcting, %.3f mm without it; %d frames reported drifted\n",
              real_name(), kFrames, corrected.mean_position_error_mm, off.mean_position_error_mm,
              count_reason(reported, StatusReason::kDrift));
  TEST_EQUAL("with the check on no frame is lost", count_status(corrected, TrackingStatus::kLost), 0);
  TEST_EQUAL("without thin lines the check reports no frame drifted", count_reason(reported, StatusReason::kDrift), 0);
  TEST("the check that reports changes no pose or status", same_frames(reported, off), true);
  TEST("the check that corrects changes no pose or status", same_frames(corrected, off), true);
}

TESTMAIN(test_rolling_shutter_tracking_cube)
TESTMAIN(test_rolling_shutter_drift_check_cube)
