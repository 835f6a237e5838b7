// SPDX-License-Identifier: BSD-3-Clause
/// The tracker's buffers grow to the largest frame seen and no further: along a moving sequence,
/// a call to Tracker::track allocates only when its frame has more control points or matches
/// than every frame before it.
#include <cstdio>
#include <vector>

#include "allocation_counter.h"
#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

static void test_tracker_allocations_along_a_sequence() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const int frames = 20;
  const std::vector<Se3> truth = true_poses(Scene::kCube, frames);
  Result<Tracker> tracker = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  TEST("the tracker starts", tracker.ok(), true);
  if (!tracker.ok()) return;
  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame frame;
  size_t most_points = 0, most_matches = 0;
  int growing = 0, allocating = 0, unexplained = 0;
  for (int k = 0; k < frames; ++k) {
    renderer.render(model.value(), truth[k], static_cast<uint32_t>(1000 + k), frame);
    const AllocationCount before = allocation_count();
    const FrameResult result = tracker.value().track(rgb565_view(frame)).value();
    const AllocationCount after = allocation_count();
    const size_t points = static_cast<size_t>(result.points_sampled), matches = tracker.value().matches().size();
    const bool grew = points > most_points || matches > most_matches;
    most_points = points > most_points ? points : most_points;
    most_matches = matches > most_matches ? matches : most_matches;
    growing += grew;
    if (after.allocations == before.allocations) continue;
    ++allocating;
    unexplained += !grew;
  }
  std::printf("Tracker::track along %d frames: %d allocated, %d had more points or matches than every frame before\n",
              frames, allocating, growing);
  TEST("no frame allocates unless it has more points or matches than every earlier one", unexplained, 0);
  TEST("the first frame allocated its buffers", allocating >= 1, true);
  TEST("the sequence was tracked", most_matches > 20, true);
}

TESTMAIN(test_tracker_allocations_along_a_sequence)


