// SPDX-License-Identifier: BSD-3-Clause
/// Frames above the detector's side (kMaxDetectionSide, 480 px on the shorter side) through the
/// library alone: a generated QVGA trial of the cube (detection_scene.h, test_auto_init's view)
/// enlarged 4 and 8 times by repeating each pixel, 1280x960 and 2560x1920 with the camera scaled
/// alike (the same rays), is found by Detector within 2 mm and 2 degrees of the truth from
/// templates made for the large camera, the detector reducing the frame itself (by 2 and 4, to
/// 640x480); and AutoInitTracker, fed the 1280x960 frame, finds the cube on it and tracks it
/// there at full size, within the same bounds.
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
constexpr uint32_t kView = 11;  // test_auto_init's first view, found at QVGA
constexpr double kMaxCentreMm = 2, kMaxRotationDeg = 2;

/// `frame` with each pixel repeated `factor` times along each axis.
Rgb565Frame enlarged(const Rgb565Frame& frame, int factor) {
  Rgb565Frame large;
  large.width = frame.width * factor;
  large.height = frame.height * factor;
  large.pixels.resize(static_cast<size_t>(large.width) * static_cast<size_t>(large.height));
  for (int y = 0; y < large.height; ++y)
    for (int x = 0; x < large.width; ++x)
      large.pixels[static_cast<size_t>(y) * static_cast<size_t>(large.width) + static_cast<size_t>(x)] =
          frame.pixels[static_cast<size_t>(y / factor) * static_cast<size_t>(frame.width) + static_cast<size_t>(x / factor)];
  return large;
}

bool within_bounds(const PoseError& e) { return e.centre_mm <= kMaxCentreMm && e.rotation_deg <= kMaxRotationDeg; }

}  // namespace

static void test_detection_large_frames() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera qvga = qvga_camera();
  const TemplateParams params = oblique_range();
  const Se3 truth = random_view(model.value(), qvga, params.views, kView);
  Rgb565Frame small;
  render_trial(model.value(), qvga, truth, true, kLines, 1, small);
  for (int factor : {4, 8}) {
    const PinholeCamera camera = qvga.scaled(factor);
    const Rgb565Frame frame = enlarged(small, factor);
    const FrameView view = packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565);
    std::printf("%dx%d, detected reduced by %d\n", camera.width, camera.height, detection_reduction(camera));
    TEST("the frame is above the detector's side", detection_reduction(camera) > 1, true);
    const Result<TemplateSet> templates = make_template_set(model.value(), camera, params);
    TEST("templates are made for the large camera", templates.ok(), true);
    if (!templates.ok()) return;
    const Vec3 centre = templates.value().extent.centre;
    Result<Detector> detector =
        Detector::create(model.value(), camera, templates.value(), DetectorParams{}, TrackerParams{});
    TEST("the detector is made", detector.ok(), true);
    if (!detector.ok()) return;
    const Result<Detection> detection = detector.value().detect(view);
    TEST("the full-size frame is accepted", detection.ok(), true);
    if (!detection.ok()) return;
    const PoseError e = pose_error(detection.value().camera_from_model, truth, centre, cube_symmetries());
    std::printf("  found %d, %.3f mm %.3f deg from the truth\n", detection.value().found, e.centre_mm, e.rotation_deg);
    TEST("the cube is found", detection.value().found, true);
    TEST("within 2 mm and 2 degrees of the truth", within_bounds(e), true);
    if (factor != 4) continue;
    Result<AutoInitTracker> tracker =
        AutoInitTracker::create(model.value(), camera, templates.value(), DetectorParams{}, TrackerParams{});
    TEST("the tracker is made", tracker.ok(), true);
    if (!tracker.ok()) return;
    const Result<FrameResult> result = tracker.value().track(view);
    TEST("AutoInitTracker accepts the full-size frame", result.ok(), true);
    if (!result.ok()) return;
    const PoseError tracked = pose_error(result.value().camera_from_model, truth, centre, cube_symmetries());
    std::printf("  AutoInitTracker: detected %d found %d, %s, %.3f mm %.3f deg\n", tracker.value().detected(),
                tracker.value().found(), status_name(result.value().status), tracked.centre_mm, tracked.rotation_deg);
    TEST("AutoInitTracker finds the cube on it", tracker.value().found(), true);
    TEST("and tracks it there (uncertain until confirmed)", result.value().reason, StatusReason::kUnconfirmed);
    TEST("within 2 mm and 2 degrees of the truth", within_bounds(tracked), true);
  }
}

TESTMAIN(test_detection_large_frames)
