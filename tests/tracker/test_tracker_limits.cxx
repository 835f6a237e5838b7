// SPDX-License-Identifier: BSD-3-Clause
/// A tracker created with stated maxima (TrackerLimits) allocates everything at create: along a
/// moving sequence no call to Tracker::track allocates, and the poses are the same, bit for bit,
/// as those of a tracker whose buffers grow. A frame over the control-point maximum is lost with
/// kOverLimit, allocating nothing; create refuses a model, a camera or limits that do not fit.
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

namespace {

TrackerLimits qvga_limits(int control_points) {
  TrackerLimits limits;
  limits.primitives = 32;
  limits.control_points = control_points;
  limits.image_width = 320;
  limits.image_height = 240;
  limits.colour_frames = true;  // the sequence is RGB565
  return limits;
}

/// Tracks the first `frames` of `truth` with `tracker` and returns the heap allocations its
/// Tracker::track calls made (the rendering's are not counted).
uint64_t track_allocations(Tracker& tracker, const EdgeModel& model, const std::vector<Se3>& truth, int frames,
                           SceneRenderer& renderer, Rgb565Frame& frame) {
  uint64_t allocations = 0;
  for (int k = 0; k < frames; ++k) {
    renderer.render(model, truth[static_cast<size_t>(k)], static_cast<uint32_t>(1000 + k), frame);
    const AllocationCount before = allocation_count();
    tracker.track(rgb565_view(frame)).value();
    allocations += allocation_count().allocations - before.allocations;
  }
  return allocations;
}

}  // namespace

static void test_tracker_limits() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const int frames = 20;
  const std::vector<Se3> truth = true_poses(Scene::kCube, frames);
  Result<Tracker> growing = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  Result<Tracker> bounded = Tracker::create(model.value(), camera, truth[0], TrackerParams{}, qvga_limits(128));
  Result<Tracker> too_few = Tracker::create(model.value(), camera, truth[0], TrackerParams{}, qvga_limits(8));
  TEST("the trackers start", growing.ok() && bounded.ok() && too_few.ok(), true);
  if (!growing.ok() || !bounded.ok() || !too_few.ok()) return;
  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame frame;
  uint64_t bounded_allocations = 0, over_limit_allocations = 0;
  int same = 0, tracked = 0, over_limit = 0;
  for (int k = 0; k < frames; ++k) {
    renderer.render(model.value(), truth[k], static_cast<uint32_t>(1000 + k), frame);
    const FrameResult free_result = growing.value().track(rgb565_view(frame)).value();
    AllocationCount before = allocation_count();
    const FrameResult bounded_result = bounded.value().track(rgb565_view(frame)).value();
    bounded_allocations += allocation_count().allocations - before.allocations;
    before = allocation_count();
    const FrameResult over = too_few.value().track(rgb565_view(frame)).value();
    over_limit_allocations += allocation_count().allocations - before.allocations;
    same += same_bits(free_result.camera_from_model, bounded_result.camera_from_model) &&
            free_result.status == bounded_result.status;
    tracked += bounded_result.status == TrackingStatus::kTracked;
    over_limit += over.status == TrackingStatus::kLost && over.reason == StatusReason::kOverLimit &&
                  over.points_sampled == 0 && too_few.value().matches().empty();
  }
  std::printf("Tracker::track with TrackerLimits along %d frames: %llu allocations, %d poses as the growing tracker's\n",
              frames, static_cast<unsigned long long>(bounded_allocations), same);
  TEST("no frame of a tracker created with limits allocates", bounded_allocations, uint64_t{0});
  TEST("its poses and statuses are the growing tracker's, bit for bit", same, frames);
  TEST("the sequence was tracked", tracked, frames);
  TEST("every frame over the control-point limit is lost as such, with nothing searched", over_limit, frames);
  TEST("and allocates nothing", over_limit_allocations, uint64_t{0});
  TEST("the limits are the tracker's", bounded.value().limits().control_points, 128);
  Tracker copy = bounded.value();
  const AllocationCount before_copy_tracks = allocation_count();
  copy.track(rgb565_view(frame)).value();
  TEST("a copy allocates its buffers when copied, not when it tracks",
       allocation_count().allocations - before_copy_tracks.allocations, uint64_t{0});

  // The drift check's second solve and its correction, forced on every frame where the thin-line
  // test calls any match a line (a check_sigmas that every pull passes, drift_check.h): it uses
  // the tracker's own matches and workspace, so it allocates nothing either.
  TrackerParams checking;
  checking.thin_lines.check = DriftAction::kCorrect;
  checking.thin_lines.check_sigmas = real(0.001);
  Result<Tracker> checked = Tracker::create(model.value(), camera, truth[0], checking, qvga_limits(128));
  TEST("a tracker with limits and the drift check forced starts", checked.ok(), true);
  if (!checked.ok()) return;
  TEST("and none of its frames allocates",
       track_allocations(checked.value(), model.value(), truth, frames, renderer, frame), uint64_t{0});

  // Through a lens and a rolling shutter the tracker keeps more per point (the shared projections,
  // the points as sampled and moved); with limits they too are allocated at create.
  PinholeCamera lens_camera = camera;
  lens_camera.lens.model = LensModel::kVisp;
  lens_camera.lens.kud = real(-0.05);
  lens_camera.lens.kdu = real(0.05);
  TrackerParams rolling;
  rolling.readout = real(0.5);
  Result<Tracker> lens_bounded = Tracker::create(model.value(), lens_camera, truth[0], rolling, qvga_limits(128));
  TEST("a tracker with limits, a lens and a rolling shutter starts", lens_bounded.ok(), true);
  if (!lens_bounded.ok()) return;
  TEST("and none of its frames allocates",
       track_allocations(lens_bounded.value(), model.value(), truth, frames, renderer, frame), uint64_t{0});

  // What create refuses.
  TrackerLimits small_model = qvga_limits(128);
  small_model.primitives = 4;
  TEST("a model with more primitives than the limit is refused",
       Tracker::create(model.value(), camera, truth[0], TrackerParams{}, small_model).ok(), false);
  TrackerLimits small_image = qvga_limits(128);
  small_image.image_width = 160;
  TEST("a camera wider than the limit is refused",
       Tracker::create(model.value(), camera, truth[0], TrackerParams{}, small_image).ok(), false);
  TrackerLimits partial;
  partial.control_points = 128;
  const Result<Tracker> incomplete = Tracker::create(model.value(), camera, truth[0], TrackerParams{}, partial);
  TEST("limits that state one maximum and not the others are refused", incomplete.ok(), false);
  PinholeCamera unsized = camera;
  unsized.width = unsized.height = 0;
  TEST("a camera without a size is refused under limits",
       Tracker::create(model.value(), unsized, truth[0], TrackerParams{}, qvga_limits(128)).ok(), false);
  TrackerLimits grey_only = qvga_limits(128);
  grey_only.colour_frames = false;
  Result<Tracker> grey_tracker = Tracker::create(model.value(), camera, truth[0], TrackerParams{}, grey_only);
  TEST("a tracker for grey frames starts", grey_tracker.ok(), true);
  if (!grey_tracker.ok()) return;
  TEST("it holds no grey image", grey_tracker.value().memory().grey_image, size_t{0});
  TEST("and refuses an RGB565 frame with an Error", grey_tracker.value().track(rgb565_view(frame)).ok(), false);
}

TESTMAIN(test_tracker_limits)
