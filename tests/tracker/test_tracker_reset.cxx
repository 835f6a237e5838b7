// SPDX-License-Identifier: BSD-3-Clause
/// Tracker::reset continues from a given pose as a freshly created tracker would: the pose is
/// the tracker's only state between frames, so after a reset the poses are bit-identical to a
/// new tracker's from that pose. A pose behind the camera is refused and changes nothing.
#include <cstdio>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

static void test_tracker_reset() {
  const int frames = 8, restart = 3;
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(Scene::kCube, frames);
  Result<Tracker> fresh = Tracker::create(model.value(), camera, truth[restart], TrackerParams{});
  Result<Tracker> reused = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  TEST("both trackers start", fresh.ok() && reused.ok(), true);
  if (!fresh.ok() || !reused.ok()) return;

  SceneRenderer renderer(camera, SceneStyle{});
  std::vector<Rgb565Frame> images(frames);
  for (int k = 0; k < frames; ++k) renderer.render(model.value(), truth[k], static_cast<uint32_t>(1000 + k), images[k]);
  // The reused tracker runs a few frames first, so its buffers hold an older frame's state.
  for (int k = 0; k < restart; ++k) reused.value().track(rgb565_view(images[k])).value();

  const Se3 before = reused.value().camera_from_model();
  const Se3 behind(Mat33::identity(), Vec3{real(0), real(0), real(-0.2)});
  TEST("a pose behind the camera is refused", reused.value().reset(behind), false);
  TEST("and leaves the pose as it was", same_bits(reused.value().camera_from_model(), before), true);

  TEST("a pose in front of the camera is taken", reused.value().reset(truth[restart]), true);
  TEST("and is the pose from then on", same_bits(reused.value().camera_from_model(), truth[restart]), true);
  int identical = 0, matched = 0;
  for (int k = restart; k < frames; ++k) {
    const FrameResult a = fresh.value().track(rgb565_view(images[k])).value();
    const FrameResult b = reused.value().track(rgb565_view(images[k])).value();
    identical += same_bits(a.camera_from_model, b.camera_from_model) && a.points_matched == b.points_matched;
    matched += b.points_matched;
  }
  std::printf("%s: %d of %d frames identical after the reset, %d points matched\n", real_name(), identical,
              frames - restart, matched);
  TEST("the frames after the reset track (the comparison is not vacuous)", matched > 30 * (frames - restart), true);
  TEST_EQUAL("after a reset, tracking is bit-identical to a new tracker's", identical, frames - restart);
}

TESTMAIN(test_tracker_reset)
