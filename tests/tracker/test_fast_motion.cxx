// SPDX-License-Identifier: BSD-3-Clause
/// Fast motion on the default settings (range 4, step 10): the generated cube and wood toy
/// sequences sped up five times (every 5th pose of the 300-frame trajectories, 13-15 px per QVGA
/// frame) are tracked with no lost frame and a mean camera position error under 0.5 mm, thanks
/// to the constant-velocity prediction and the range that follows the predicted motion, and
/// every frame within 0.5 mm of the truth is reported tracked; each
/// `real` stays near the double run (S40.23 within 0.1 mm in every frame).
#include <cstdio>

#include "edgetrack/model_io.h"
#include "golden.h"
#include "golden_check.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr double kAccurateMm = 0.5;  ///< a camera position this close to the truth is tracked

void check_fast(Scene scene, const char* name) {
  SequenceSpec spec;
  spec.subsample = kFastSpeedUp;
  const SequenceRun run = run_sequence(scene, kFastFrames, false, TrackerParams{}, spec);
  TEST((std::string("the fast ") + name + " sequence runs").c_str(), run.loaded, true);
  if (!run.loaded) return;
  const Result<EdgeModel> model = load_model(model_path(scene));
  const double motion = largest_vertex_motion(model.value(), qvga_camera(), run.truth);
  unsigned widest = 0;
  for (const FrameResult& f : run.frames) widest = f.measures.range > widest ? f.measures.range : widest;
  std::printf("%s %s: largest vertex motion %.2f px per frame, mean error %.3f mm, %d uncertain, %d lost, widest "
              "range %u px\n",
              real_name(), name, motion, run.mean_position_error_mm, count_status(run, TrackingStatus::kUncertain),
              count_status(run, TrackingStatus::kLost), widest);
  TEST("the motion is 12 to 15 px per QVGA frame", motion >= 12.0 && motion <= 15.0, true);
  TEST_EQUAL("no frame is lost", count_status(run, TrackingStatus::kLost), 0);
  TEST_NEAR("mean camera position error is below 0.5 mm", run.mean_position_error_mm, 0, 0.5);
  // A correction against the prediction is large wherever the motion changes; the status reads
  // what the matches support, so a frame tracked this close to the truth is reported tracked.
  int accurate_not_tracked = 0;
  for (size_t k = 0; k < run.frames.size(); ++k)
    accurate_not_tracked += run.position_error_mm[k] < kAccurateMm && run.frames[k].status != TrackingStatus::kTracked;
  TEST_EQUAL("every frame within 0.5 mm of the truth is reported tracked", accurate_not_tracked, 0);
  compare_with_golden(golden_name(scene, kFastSpeedUp), run);
}

}  // namespace

static void test_fast_motion_cube() { check_fast(Scene::kCube, "cube"); }
static void test_fast_motion_wood_toy() { check_fast(Scene::kWoodToy, "wood toy"); }

TESTMAIN(test_fast_motion_cube)
TESTMAIN(test_fast_motion_wood_toy)
