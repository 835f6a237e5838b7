// SPDX-License-Identifier: BSD-3-Clause
/// Thread safety as docs/API.md states it: one Tracker per thread. Two trackers, on two scenes,
/// tracked at the same time in two threads give bit for bit the poses each gives alone.
#include <cstdio>
#include <thread>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// A scene's rendered frames and the model, made before any thread starts.
struct Sequence {
  EdgeModel model;
  std::vector<Se3> truth;
  std::vector<Rgb565Frame> frames;
};

Sequence make_sequence(Scene scene, int frames) {
  Sequence s;
  s.model = load_model(model_path(scene)).value();
  s.truth = true_poses(scene, frames);
  SceneRenderer renderer(qvga_camera(), SceneStyle{});
  s.frames.resize(static_cast<size_t>(frames));
  for (int k = 0; k < frames; ++k) renderer.render(s.model, s.truth[static_cast<size_t>(k)], 500u + k, s.frames[k]);
  return s;
}

/// The poses of a tracker created from the first true pose, one per frame.
std::vector<Se3> track_all(const Sequence& s) {
  std::vector<Se3> poses;
  Result<Tracker> tracker = Tracker::create(s.model, qvga_camera(), s.truth[0], TrackerParams{});
  if (!tracker.ok()) return poses;
  for (const Rgb565Frame& frame : s.frames) {
    Result<FrameResult> r = tracker.value().track(rgb565_view(frame));
    if (!r.ok()) break;
    poses.push_back(r.value().camera_from_model);
  }
  return poses;
}

int identical(const std::vector<Se3>& a, const std::vector<Se3>& b) {
  int same = 0;
  for (size_t k = 0; k < a.size() && k < b.size(); ++k) same += same_bits(a[k], b[k]);
  return same;
}

}  // namespace

static void test_two_threads() {
  const int frames = 12;
  const Sequence cube = make_sequence(Scene::kCube, frames), toy = make_sequence(Scene::kWoodToy, frames);
  const std::vector<Se3> cube_alone = track_all(cube), toy_alone = track_all(toy);
  TEST_EQUAL("the cube tracks alone", static_cast<int>(cube_alone.size()), frames);
  TEST_EQUAL("the wood toy tracks alone", static_cast<int>(toy_alone.size()), frames);
  std::vector<Se3> cube_threaded, toy_threaded;
  std::thread first([&] { cube_threaded = track_all(cube); });
  std::thread second([&] { toy_threaded = track_all(toy); });
  first.join();
  second.join();
  std::printf("%s: %d and %d of %d poses bit for bit\n", real_name(), identical(cube_alone, cube_threaded),
              identical(toy_alone, toy_threaded), frames);
  TEST_EQUAL("the cube's poses in a thread beside another tracker are the single-thread ones",
             identical(cube_alone, cube_threaded), frames);
  TEST_EQUAL("and the wood toy's", identical(toy_alone, toy_threaded), frames);
}

TESTMAIN(test_two_threads)
