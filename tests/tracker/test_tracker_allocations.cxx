// SPDX-License-Identifier: BSD-3-Clause
/// Tracking leaves nothing behind: tracking the same frame from the same pose again and again,
/// every call to Tracker::track makes the same number of heap allocations and ends with the
/// same bytes live, so a long run's memory stays flat. Prints the allocations per frame (the
/// figure docs/RELIABILITY.md reports).
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
  Result<Tracker> tracker = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
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
  // The first frames may grow buffers the tracker keeps; from the third on, nothing may change.
  bool same_count = true, same_live = true;
  const uint64_t per_frame = after[2].allocations - before[2].allocations;
  for (int k = 3; k < repeats; ++k) {
    same_count = same_count && after[k].allocations - before[k].allocations == per_frame;
    same_live = same_live && after[k].live_bytes == after[2].live_bytes;
  }
  std::printf("Tracker::track: %llu heap allocations per frame (QVGA cube, default settings, real = %s)\n",
              static_cast<unsigned long long>(per_frame), real_name());
  TEST("every repeat of the same frame allocates the same number of times", same_count, true);
  TEST("and leaves the same bytes live: nothing accumulates between frames", same_live, true);
  TEST("the frame was tracked", tracker.value().matches().size() > 20, true);
}

TESTMAIN(test_tracker_allocations)
