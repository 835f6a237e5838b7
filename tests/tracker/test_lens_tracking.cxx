// SPDX-License-Identifier: BSD-3-Clause
/// Tracking through a lens: the generated cube seen through ViSP's radial model with
/// kud = -0.25 (a wide lens's barrel) and the wood toy through kud = +0.12 (pincushion) and -0.25, QVGA.
/// Given the lens, the tracker keeps the error within 1.2 times that of the same frames without
/// a lens (issue 26's target); left with the pinhole (the distortion ignored) it is over 5 times worse.
#include <cstdio>
#include <string>

#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kFrames = 8;

void check_lens(Scene scene, const char* name, double kud) {
  SequenceSpec spec;
  spec.lens.model = LensModel::kVisp;
  spec.lens.kud = real(kud);
  const SequenceRun given = run_sequence(scene, kFrames, false, TrackerParams{}, spec);
  spec.lens_given = false;
  const SequenceRun ignored = run_sequence(scene, kFrames, false, TrackerParams{}, spec);
  const SequenceRun plain = run_sequence(scene, kFrames, false, TrackerParams{}, SequenceSpec{});
  TEST((std::string("the ") + name + " sequences run").c_str(), given.loaded && ignored.loaded && plain.loaded, true);
  if (!given.loaded || !ignored.loaded || !plain.loaded) return;
  std::printf("%s %s through kud = %+.2f, %d frames: mean camera position error %.3f mm with the lens given, %.3f mm "
              "ignoring it, %.3f mm on the same frames without a lens; lost %d, %d, %d\n",
              real_name(), name, kud, kFrames, given.mean_position_error_mm, ignored.mean_position_error_mm,
              plain.mean_position_error_mm, count_status(given, TrackingStatus::kLost),
              count_status(ignored, TrackingStatus::kLost), count_status(plain, TrackingStatus::kLost));
  TEST_EQUAL("with the lens given no frame is lost", count_status(given, TrackingStatus::kLost), 0);
  TEST("with the lens given the error is within 1.2 times that without a lens",
       given.mean_position_error_mm <= 1.2 * plain.mean_position_error_mm, true);
  TEST("ignoring the lens is at least 5 times worse than giving it",
       ignored.mean_position_error_mm >= 5 * given.mean_position_error_mm, true);
}

}  // namespace

static void test_lens_tracking_cube() { check_lens(Scene::kCube, "cube", -0.25); }
static void test_lens_tracking_wood_toy() { check_lens(Scene::kWoodToy, "wood toy", 0.12); }
static void test_lens_tracking_wood_toy_barrel() { check_lens(Scene::kWoodToy, "wood toy", -0.25); }

TESTMAIN(test_lens_tracking_cube)
TESTMAIN(test_lens_tracking_wood_toy)
TESTMAIN(test_lens_tracking_wood_toy_barrel)
