// SPDX-License-Identifier: BSD-3-Clause
/// The generated cube played forwards and then backwards, as the long reliability run does
/// (docs/results/reliability.md), at the paper's speed and four times faster: no frame lost and
/// the mean camera position error under 0.5 mm, the turn included (at four times the speed the
/// motion reverses by about 6 px from one frame to the next).
#include <cstdio>
#include <string>
#include <vector>

#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// `frames` poses of the scene's path `speed` times faster, then the same poses back to the first.
std::vector<Se3> there_and_back(Scene scene, int frames, int speed) {
  std::vector<Se3> poses = true_poses(scene, frames, speed);
  for (int k = frames - 2; k >= 0; --k) poses.push_back(poses[static_cast<size_t>(k)]);
  return poses;
}

void check_there_and_back(Scene scene, const char* name, int frames, int speed) {
  SequenceSpec spec;
  spec.poses = there_and_back(scene, frames, speed);
  const SequenceRun run = run_sequence(scene, static_cast<int>(spec.poses.size()), false, TrackerParams{}, spec);
  const std::string label = std::string(name) + ", " + std::to_string(speed) + " times the paper's speed";
  TEST((label + ": the sequence runs").c_str(), run.loaded, true);
  if (!run.loaded) return;
  std::printf("%s %s: %zu frames, mean error %.3f mm, %d uncertain, %d lost\n", real_name(), label.c_str(),
              run.frames.size(), run.mean_position_error_mm, count_status(run, TrackingStatus::kUncertain),
              count_status(run, TrackingStatus::kLost));
  TEST_EQUAL((label + ": no frame is lost").c_str(), count_status(run, TrackingStatus::kLost), 0);
  TEST_NEAR((label + ": mean camera position error below 0.5 mm").c_str(), run.mean_position_error_mm, 0, 0.5);
}

}  // namespace

static void test_back_and_forth() {
  check_there_and_back(Scene::kCube, "cube", 60, 1);
  check_there_and_back(Scene::kCube, "cube", 40, 4);
}

TESTMAIN(test_back_and_forth)
