// SPDX-License-Identifier: BSD-3-Clause
/// On-demand grey scaling is exact: tracking a generated sequence with the grey step converting
/// only the boxes the moving edges read gives bit-identical poses and matches, every frame, to
/// converting the whole frame (the paper's way), and converts far fewer pixels.
#include <cstdio>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

bool same_matches(const std::vector<EdgeMatch>& a, const std::vector<EdgeMatch>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k) {
    const EdgeMatch &x = a[k], &y = b[k];
    if (x.point.edge != y.point.edge || x.point.pixel.x != y.point.pixel.x || x.point.pixel.y != y.point.pixel.y ||
        x.found.x != y.found.x || x.found.y != y.found.y || x.outlier != y.outlier ||
        x.alternative_count != y.alternative_count || x.chosen != y.chosen)
      return false;
    for (int h = 0; h < x.alternative_count; ++h)
      if (x.alternatives[h].x != y.alternatives[h].x || x.alternatives[h].y != y.alternatives[h].y) return false;
  }
  return true;
}

/// Tracks `frames` frames of `scene` twice, side by side, once per grey mode.
void compare_grey_modes(Scene scene, int frames) {
  const Result<EdgeModel> model = load_model(model_path(scene));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(scene, frames);
  TrackerParams on_demand_params, whole_params;
  on_demand_params.grey = GreyScaling::kOnDemand;
  whole_params.grey = GreyScaling::kWholeFrame;
  Result<Tracker> on_demand = Tracker::create(model.value(), camera, truth[0], on_demand_params);
  Result<Tracker> whole = Tracker::create(model.value(), camera, truth[0], whole_params);
  TEST("both trackers start", on_demand.ok() && whole.ok(), true);
  if (!on_demand.ok() || !whole.ok()) return;

  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame frame;
  int same_poses = 0, same_match_lists = 0, matches = 0;
  double on_demand_pixels = 0, whole_pixels = 0;
  for (int k = 0; k < frames; ++k) {
    renderer.render(model.value(), truth[k], static_cast<uint32_t>(1000 + k), frame);
    const FrameResult a = on_demand.value().track(rgb565_view(frame)).value();
    const FrameResult b = whole.value().track(rgb565_view(frame)).value();
    same_poses += same_bits(a.camera_from_model, b.camera_from_model);
    same_match_lists += same_matches(on_demand.value().matches(), whole.value().matches());
    matches += static_cast<int>(on_demand.value().matches().size());
    on_demand_pixels += a.grey_pixels;
    whole_pixels += b.grey_pixels;
  }
  std::printf("%s, %d frames: %.0f of %.0f pixels converted per frame on demand (%.1f %%), %.1f matches per frame\n",
              real_name(), frames, on_demand_pixels / frames, whole_pixels / frames,
              100 * on_demand_pixels / whole_pixels, double(matches) / frames);
  TEST_EQUAL("whole-frame grey converts every pixel of every frame", whole_pixels,
             double(frames) * camera.width * camera.height);
  TEST("the moving edges find matches (the comparison is not vacuous)", matches > 30 * frames, true);
  TEST_EQUAL("on-demand and whole-frame grey give bit-identical poses every frame", same_poses, frames);
  TEST_EQUAL("and bit-identical matches every frame", same_match_lists, frames);
  TEST("on demand converts under a quarter of the pixels", on_demand_pixels < whole_pixels / 4, true);
}

}  // namespace

static void test_tracker_grey() {
  compare_grey_modes(Scene::kCube, 30);
  compare_grey_modes(Scene::kWoodToy, 15);
}

TESTMAIN(test_tracker_grey)
