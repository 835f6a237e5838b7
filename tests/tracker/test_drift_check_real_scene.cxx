// SPDX-License-Identifier: BSD-3-Clause
/// The drift check, on by default, raises no false alarm on a real scene (issue #27): ViSP's
/// mbt/cube with its cube.xml, with cube.cao and with cube_and_cylinder.cao (an approximate
/// model, on which the check takes its second pose on some frames, and the run then follows
/// another path than without the check), every frame is tracked, as without the check. Host
/// trees only: 218 frames of 640x480, tracked four times, are slow under QEMU.
#include <cstdio>

#include "edgetrack/drift_check.h"
#include "edgetrack/model_io.h"
#include "edgetrack/visp_config.h"
#include "testlib/testlib_test.h"
#include "visp_sequence.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kFrames = 218;  // the whole sequence

void check_model(const char* model_file) {
  const std::string mbt = std::string(EDGETRACK_VISP_IMAGES) + "/mbt/";
  const SequenceRun checked = run_visp_cube(EDGETRACK_VISP_IMAGES, kFrames, {}, {}, model_file);
  const SequenceRun plain = run_visp_cube(
      EDGETRACK_VISP_IMAGES, kFrames, {}, [](TrackerParams& p) { p.thin_lines.check = DriftAction::kNone; }, model_file);
  TEST("both runs load", checked.loaded && plain.loaded, true);
  if (!checked.loaded || !plain.loaded) return;
  const Result<EdgeModel> model = load_model(mbt + model_file);
  if (!model.ok()) return;
  TrackerConfig config;
  if (!apply_visp_config(mbt + "cube.xml", config).ok()) return;
  PinholeCamera camera = config.camera;
  camera.width = 640;
  camera.height = 480;
  int changed = 0;  // frames whose pose differs from the run without the check
  double largest_px = 0;
  for (int k = 0; k < kFrames; ++k) {
    const double px = static_cast<double>(largest_overlay_distance_px(
        model.value(), camera, checked.frames[k].pose.camera_from_model, plain.frames[k].pose.camera_from_model));
    changed += px > 0;
    largest_px = px > largest_px ? px : largest_px;
  }
  std::printf("%s mbt/cube %s, %d frames: tracked %d with the default check, %d without; %d frames differ, the "
              "overlays by at most %.3f px\n",
              real_name(), model_file, kFrames, count_status(checked, TrackingStatus::kTracked),
              count_status(plain, TrackingStatus::kTracked), changed, largest_px);
  TEST_EQUAL("without the check every frame is tracked", count_status(plain, TrackingStatus::kTracked), kFrames);
  TEST_EQUAL("with the default check every frame is tracked: no false alarm",
             count_status(checked, TrackingStatus::kTracked), kFrames);
}

}  // namespace

static void test_drift_check_real_scene() {
  check_model("cube_and_cylinder.cao");
  check_model("cube.cao");
}

TESTMAIN(test_drift_check_real_scene)
