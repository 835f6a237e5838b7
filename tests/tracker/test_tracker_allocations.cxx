// SPDX-License-Identifier: BSD-3-Clause
/// Tracking allocates nothing once its buffers have grown: tracking the same frame from the same
/// pose again and again, no call to Tracker::track after the first makes a heap allocation and
/// the live bytes stay the same, so a long run's memory stays flat. Prints the allocations per
/// frame (the figure docs/RELIABILITY.md reports).
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

static void test_tracker_allocations() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(Scene::kCube, 2);
  const AllocationCount at_start = allocation_count();
  Result<Tracker> tracker = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  const int64_t created_bytes = allocation_count().live_bytes - at_start.live_bytes;
  TEST("the tracker starts", tracker.ok(), true);
  if (!tracker.ok()) return;
  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame frame;
  renderer.render(model.value(), truth[1], 7, frame);

  const int repeats = 12;
  std::vector<AllocationCount> before(repeats), after(repeats);
  for (int k = 0; k < repeats; ++k) {
    tracker.value().reset(truth[0]);
    before[k] = allocation_count();
    tracker.value().track(rgb565_view(frame)).value();
    after[k] = allocation_count();
  }
  // The first frame grows the buffers the tracker keeps; after it, nothing may change.
  uint64_t after_first = 0;
  bool same_live = true;
  for (int k = 1; k < repeats; ++k) {
    after_first += after[k].allocations - before[k].allocations;
    same_live = same_live && after[k].live_bytes == after[1].live_bytes;
  }
  std::printf("Tracker::track: %llu heap allocations in the first frame, %llu in the %d repeats after it "
              "(QVGA cube, default settings, real = %s)\n",
              static_cast<unsigned long long>(after[0].allocations - before[0].allocations),
              static_cast<unsigned long long>(after_first), repeats - 1, real_name());
  std::printf("Tracker heap: %lld bytes live after its first frame (QVGA cube, real = %s)\n",
              static_cast<long long>(created_bytes + after[0].live_bytes - before[0].live_bytes), real_name());
  TEST("no repeat of the frame after the first allocates", after_first, uint64_t{0});
  TEST("and the live bytes stay the same: nothing accumulates between frames", same_live, true);
  TEST("the frame was tracked", tracker.value().matches().size() > 20, true);
}

TESTMAIN(test_tracker_allocations)
