// SPDX-License-Identifier: BSD-3-Clause
/// Tracking allocates nothing once its buffers have grown: tracking the same frame from the same
/// pose again and again, no call to Tracker::track after the first makes a heap allocation and
/// the live bytes stay the same, so a long run's memory stays flat. Prints the allocations per
/// frame (the figure docs/RELIABILITY.md reports).
#include <algorithm>
#include <cstdio>
#include <vector>

#include "allocation_counter.h"
#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpImageConvert.h"

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

  // Tracker::memory's buffers against the allocator's count: they are the tracker's heap, the
  // rest of which (masks, faces' states, the state object) is a few kilobytes.
  const TrackerMemory memory = tracker.value().memory();
  const int64_t counted = created_bytes + after[0].live_bytes - before[0].live_bytes;
  for (const auto& row : memory.rows()) std::printf("Tracker buffer: %s %zu bytes\n", row.name, row.bytes);
  TEST("the buffers add up to no more than the allocator counted", int64_t(memory.total()) <= counted, true);
  TEST("and to all of it but at most 32 KB", counted - int64_t(memory.total()) <= 32 * 1024, true);
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  TEST_EQUAL("an RGB565 frame is converted into a grey image of the frame's size", memory.grey_image, pixels);
  TEST_EQUAL("the Edge-ID image holds half a byte per pixel (the cube has 12 edges)", memory.edge_id_image, pixels / 2);
  TEST("the depths under the lines take less than a tenth of a depth image's", memory.edge_id_lines < pixels * 4 / 10,
       true);
  // One line's depths at a time: less than a longest line's 4-byte depths for each of the 12 edges.
  const size_t longest_line = static_cast<size_t>(std::max(camera.width, camera.height) + 1);
  TEST("and are kept for one line at a time", memory.edge_id_lines < 12 * longest_line * sizeof(int32_t), true);

  // A grey8 frame is read in place: no grey image, and the same pose as from RGB565 (the grey
  // levels are rgb565ToGrey's either way).
  std::vector<unsigned char> grey(pixels);
  for (size_t i = 0; i < pixels; ++i) grey[i] = vpImageConvert::rgb565ToGrey(frame.pixels[i]);
  Result<Tracker> grey_tracker = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  const FrameResult from_grey =
      grey_tracker.value().track(packed_frame(grey.data(), camera.width, camera.height, PixelLayout::kGrey8)).value();
  TEST_EQUAL("a tracker fed grey8 frames keeps no grey image", grey_tracker.value().memory().grey_image, size_t{0});
  tracker.value().reset(truth[0]);
  const FrameResult from_rgb565 = tracker.value().track(rgb565_view(frame)).value();
  const Vec3 t_grey = from_grey.camera_from_model.translation(), t_rgb565 = from_rgb565.camera_from_model.translation();
  const Vec3 r_grey = from_grey.camera_from_model.theta_u(), r_rgb565 = from_rgb565.camera_from_model.theta_u();
  TEST("and tracks to the same pose", t_grey.x == t_rgb565.x && t_grey.y == t_rgb565.y && t_grey.z == t_rgb565.z &&
                                          r_grey.x == r_rgb565.x && r_grey.y == r_rgb565.y && r_grey.z == r_rgb565.z,
       true);
}

TESTMAIN(test_tracker_allocations)
