// SPDX-License-Identifier: BSD-3-Clause
/// Multiple edge hypotheses: on generated sequences with a thin bar a few pixels beyond each
/// model edge, keeping 3 hypotheses per control point and letting the pose step use the nearest
/// lowers the camera position error against one hypothesis (the strongest edge).
#include <cstdio>
#include <string>

#include "distractor_scene.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// Frames per run: short, so that the test stays fast under QEMU.
constexpr int kFrames = 20;

void compare_hypotheses(Scene scene, const char* name) {
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
  TEST((std::string("3 hypotheses lower the mean camera position error on the ") + name).c_str(),
       multiple.mean_position_error_mm < single.mean_position_error_mm, true);
}

}  // namespace

static void test_hypotheses() {
  compare_hypotheses(Scene::kCube, "cube");
  compare_hypotheses(Scene::kWoodToy, "wood toy");
}

TESTMAIN(test_hypotheses)
