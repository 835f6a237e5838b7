// SPDX-License-Identifier: BSD-3-Clause
/// Multiple edge hypotheses: on generated sequences with a thin bar a few pixels beyond each
/// model edge, the bars give the matches alternatives, and with 3 hypotheses per control point
/// (the pose step using the nearest) the tracker follows the model as closely as with one. Three
/// hypotheses lowered the error against one while the first pose solve was unweighted and sites
/// had no contrast test; one hypothesis gains more from both than three (docs/ME.md), so the
/// test states the bound both meet.
#include <cstdio>
#include <string>

#include "distractor_scene.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// Frames per run: short, so that the test stays fast under QEMU.
constexpr int kFrames = 20;

/// bound_mm: the paper's accuracy for the scene, which the tracker meets without the bars
/// (test_tracking.cxx: the cube within 1 mm, the self-occluding wood toy within 2 mm).
void compare_hypotheses(Scene scene, const char* name, double bound_mm) {
  TrackerParams one, three;
  one.hypotheses = 1;
  three.hypotheses = 3;
  const real offset(0.005), width(0.001);
  const DistractorRun single = run_with_distractors(scene, kFrames, one, offset, width);
  const DistractorRun multiple = run_with_distractors(scene, kFrames, three, offset, width);
  TEST((std::string("the ") + name + " distractor sequence runs").c_str(), single.loaded && multiple.loaded, true);
  if (!single.loaded || !multiple.loaded) return;
  std::printf("%s, %s, bars 1 mm wide 5 mm beyond each edge: K = 1 mean %.3f mm, largest %.3f mm; K = 3 mean %.3f mm, largest %.3f mm, "
              "%.2f alternatives per match\n",
              name, real_name(), single.mean_position_error_mm, single.largest_position_error_mm,
              multiple.mean_position_error_mm, multiple.largest_position_error_mm, multiple.mean_alternatives);
  TEST("the bars give the matches alternatives", multiple.mean_alternatives > 0.2, true);
  TEST_NEAR((std::string("one hypothesis: mean camera position error on the ") + name + " (mm)").c_str(),
            single.mean_position_error_mm, 0, bound_mm);
  TEST_NEAR((std::string("three hypotheses: mean camera position error on the ") + name + " (mm)").c_str(),
            multiple.mean_position_error_mm, 0, bound_mm);
}

}  // namespace

static void test_hypotheses() {
  compare_hypotheses(Scene::kCube, "cube", 1.0);
  compare_hypotheses(Scene::kWoodToy, "wood toy", 2.0);
}

TESTMAIN(test_hypotheses)
