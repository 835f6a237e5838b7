// SPDX-License-Identifier: BSD-3-Clause
/// AutoInitTracker's recovery decisions on a short generated QVGA sequence of the cube over a
/// textured background with distractor lines (detection_scene.h), with test_detection's small
/// template range: the first frame is detected on and reported uncertain until the next frame,
/// tracked from it, confirms it; each frame without the object is detected on and lost, none
/// tracked; when the cube comes back at another view, out of the tracker's own reach, it is
/// re-detected on its first frame back and tracked again on the next, within 2 mm and 2 degrees.
#include <cstdio>
#include <vector>

#include "detection_scene.h"
#include "edgetrack/detector/auto_init_tracker.h"
#include "edgetrack/model_io.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kLines = 12;

struct Shot {
  uint32_t view;  ///< random_view's seed (0: the background without the object)
  uint32_t scene;  ///< render_trial's seed: background, lines and noise
};

/// Frames 0-2 one view, 3-4 no object, 5-7 another view.
const Shot kShots[] = {{11, 1}, {11, 2}, {11, 3}, {0, 4}, {0, 5}, {13, 6}, {13, 7}, {13, 8}};
constexpr int kFirstBack = 5;

}  // namespace

static void test_auto_init_recovery() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const TemplateParams params = oblique_range();
  Result<TemplateSet> templates = make_template_set(model.value(), camera, params);
  TEST("templates are made", templates.ok(), true);
  if (!templates.ok()) return;
  const Vec3 centre = templates.value().extent.centre;
  Result<AutoInitTracker> tracker = AutoInitTracker::create(model.value(), camera, std::move(templates).value(),
                                                            DetectorParams{}, TrackerParams{});
  TEST("the tracker is made", tracker.ok(), true);
  if (!tracker.ok()) return;
  Rgb565Frame frame;
  for (int k = 0; k < static_cast<int>(sizeof kShots / sizeof kShots[0]); ++k) {
    const Shot shot = kShots[k];
    const Se3 truth = random_view(model.value(), camera, params.views, shot.view == 0 ? 11 : shot.view);
    render_trial(model.value(), camera, truth, shot.view != 0, kLines, shot.scene, frame);
    const Result<FrameResult> result =
        tracker.value().track(packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565));
    TEST("the frame is accepted", result.ok(), true);
    if (!result.ok()) return;
    const FrameResult& r = result.value();
    const PoseError e = pose_error(r.camera_from_model, truth, centre, cube_symmetries());
    std::printf("frame %d (%s): detected %d found %d, %s (%s), %.3f mm %.3f deg\n", k, shot.view ? "cube" : "none",
                tracker.value().detected(), tracker.value().found(), status_name(r.status), reason_name(r.reason),
                e.centre_mm, e.rotation_deg);
    const bool first = k == 0 || k == kFirstBack, next = k == 1 || k == kFirstBack + 1;
    if (shot.view == 0) {
      TEST("without the object no frame is tracked", r.status != TrackingStatus::kTracked, true);
      TEST("a lost frame is detected on", r.status != TrackingStatus::kLost || tracker.value().detected(), true);
      TEST("without the object nothing is found", tracker.value().found(), false);
    } else if (first) {
      TEST("the object's first frame is detected on", tracker.value().detected(), true);
      TEST("the object's first frame finds it", tracker.value().found(), true);
      TEST("a detection frame is uncertain until confirmed", r.reason, StatusReason::kUnconfirmed);
    } else {
      TEST("a frame tracked from a found pose needs no detection", tracker.value().detected(), false);
      TEST("the next frame tracks and confirms the detection", r.status, TrackingStatus::kTracked);
      TEST("the detection is confirmed", tracker.value().confirmed(), true);
    }
    if (shot.view != 0 && (first || next)) {
      TEST("the pose is within 2 mm of the truth (any symmetric pose)", e.centre_mm <= 2, true);
      TEST("the pose is within 2 degrees of the truth (any symmetric pose)", e.rotation_deg <= 2, true);
    }
  }
}

TESTMAIN(test_auto_init_recovery)
