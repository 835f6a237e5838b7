// SPDX-License-Identifier: BSD-3-Clause
/// A rolling shutter (the rows read over a whole frame interval, top first) on the fast cube
/// sequence (every 5th pose, 13-15 px per QVGA frame): the bottom row sees the cube a frame's
/// motion after the top, a shear of up to 7 px either side of the middle row that no rigid pose
/// fits. Given the readout, the tracker sees each row at its own time (rolling_shutter.h): what
/// is left of the shear's cost is the constant-velocity model's error, which must stay under a
/// quarter of that cost over the same trajectory under a global shutter. Before a velocity is
/// measured (the first two frames) the readout changes nothing, bit for bit.
#include <cstdio>

#include "golden.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kFrames = 10;
constexpr int kRenders = 16;  ///< renders a frame: rows from one at most 1 px of motion from their read time

SequenceRun run(double readout, double given) {
  SequenceSpec spec;
  spec.subsample = kFastSpeedUp;
  spec.readout = readout;
  spec.readout_renders = kRenders;
  TrackerParams params;
  params.readout = real(given);
  return run_sequence(Scene::kCube, kFrames, false, params, spec);
}

double mean_from(const SequenceRun& run, int first) {
  double sum = 0;
  for (size_t k = static_cast<size_t>(first); k < run.position_error_mm.size(); ++k) sum += run.position_error_mm[k];
  return sum / static_cast<double>(run.position_error_mm.size() - static_cast<size_t>(first));
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

TESTMAIN(test_rolling_shutter_tracking_cube)
