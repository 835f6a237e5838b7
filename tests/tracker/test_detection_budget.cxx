// SPDX-License-Identifier: BSD-3-Clause
/// The detection's work budget (DetectorParams::max_points_searched) on generated QVGA frames of
/// the wood toy (detection_scene.h's oblique range): a budget of one control point runs one frame
/// and returns (found where that frame already passed the acceptance check, else not found); a
/// small one stops within one frame past it; with any budget a pose found is right (within 2 mm
/// and 2 degrees), never a wrong one passed off as found; a detection the budget cut short is
/// found only with a confident candidate; the default budget (the PXA270's QVGA budget,
/// docs/APP.md) finds what the unlimited search finds on these frames, within it; the budget is
/// scaled by the detection frame's pixels; and AutoInitTracker reports a first frame whose
/// detection ran out of budget unfound lost, not detected.
#include <cstdio>
#include <vector>

#include "detection_scene.h"
#include "edgetrack/detector/auto_init_tracker.h"
#include "edgetrack/detector/detector.h"
#include "edgetrack/model_io.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kLines = 12;
const uint32_t kSeeds[] = {11, 12, 13};
constexpr int kSmallBudget = 600;
/// The default: the budget that keeps a QVGA detection on the PXA270 under 300 M guest
/// instructions (docs/APP.md).
const int kPxa270Budget = DetectorParams{}.max_points_searched;
/// More control points than one frame of these QVGA views holds at the refining step (5 px): the
/// wood toy 130-170 mm away spans under 150 px, its visible edges under 1000 px.
constexpr int kOneFrameMost = 400;

Result<Detector> detector_with(const EdgeModel& model, const PinholeCamera& camera, int budget) {
  Result<TemplateSet> templates = make_template_set(model, camera, oblique_range());
  if (!templates.ok()) return templates.error();
  DetectorParams params;
  params.max_points_searched = budget;
  return Detector::create(model, camera, std::move(templates).value(), params, TrackerParams{});
}

/// The budget is QVGA's, scaled by the detection frame's pixels: the same share of a frame's own
/// cost at any size.
void test_budget_scaled_by_pixels(const EdgeModel& model) {
  const PinholeCamera qvga = qvga_camera();
  TEST_EQUAL("QVGA's budget as given", scaled_points_budget(5000, qvga), 5000);
  const PinholeCamera vga(qvga.px * real(2), qvga.py * real(2), qvga.u0 * real(2), qvga.v0 * real(2), 640, 480);
  TEST_EQUAL("640 x 480: four times QVGA's pixels, four times the points", scaled_points_budget(5000, vga), 20000);
  const PinholeCamera small(qvga.px / real(2), qvga.py / real(2), qvga.u0 / real(2), qvga.v0 / real(2), 160, 120);
  TEST_EQUAL("160 x 120: a quarter", scaled_points_budget(5000, small), 1250);
  TEST_EQUAL("no budget stays none", scaled_points_budget(0, vga), 0);
  TEST_EQUAL("a budget is at least one point", scaled_points_budget(1, small), 1);
  TEST_EQUAL("no overflow on a large budget and frame", scaled_points_budget(1000000000, vga) > 1000000000, true);
  TEST("the default is a budget", DetectorParams{}.max_points_searched > 0, true);
  // A detector at 640 x 480 searches the scaled budget (its templates made at that camera).
  TemplateParams few = oblique_range();
  few.views.subdivisions = 0;
  few.views.in_plane_steps = 4;
  Result<TemplateSet> templates = make_template_set(model, vga, few);
  TEST("templates at 640 x 480 are made", templates.ok(), true);
  if (!templates.ok()) return;
  Result<Detector> detector = Detector::create(model, vga, std::move(templates).value(), DetectorParams{}, TrackerParams{});
  TEST("a default detector at 640 x 480 is made", detector.ok(), true);
  if (detector.ok())
    TEST_EQUAL("  its budget: the default scaled to its pixels", detector.value().points_budget(),
               4 * DetectorParams{}.max_points_searched);
}

}  // namespace

static void test_detection_budget() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kWoodToy));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  test_budget_scaled_by_pixels(model.value());
  const PinholeCamera camera = qvga_camera();
  const Vec3 centre = model_extent(model.value()).centre;
  Result<Detector> tiny = detector_with(model.value(), camera, 1);
  Result<Detector> small = detector_with(model.value(), camera, kSmallBudget);
  Result<Detector> unlimited = detector_with(model.value(), camera, 0);
  Result<Detector> pxa270 = detector_with(model.value(), camera, kPxa270Budget);
  TEST("the detectors are made", tiny.ok() && small.ok() && unlimited.ok() && pxa270.ok(), true);
  if (!tiny.ok() || !small.ok() || !unlimited.ok() || !pxa270.ok()) return;
  TEST_EQUAL("at QVGA the budget is as given", pxa270.value().points_budget(), kPxa270Budget);
  TEST_EQUAL("  and none stays none", unlimited.value().points_budget(), 0);
  Rgb565Frame frame;
  int not_found = 0;
  for (const uint32_t seed : kSeeds) {
    const Se3 truth = random_view(model.value(), camera, oblique_range().views, seed);
    render_trial(model.value(), camera, truth, true, kLines, seed, frame);
    const FrameView view = packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565);
    const Detection none_left = tiny.value().detect(view).value();
    const Detection some = small.value().detect(view).value();
    const Detection all = unlimited.value().detect(view).value();
    const PoseError e_some = pose_error(some.camera_from_model, truth, centre, {Mat33::identity()});
    const PoseError e_all = pose_error(all.camera_from_model, truth, centre, {Mat33::identity()});
    std::printf("seed %u: budget 1: %d frames, %d points, found %d; budget %d: %d frames, %d points, found %d "
                "(%.3f mm %.3f deg); none: %d frames, %d points, found %d (%.3f mm %.3f deg)\n",
                seed, none_left.frames, none_left.points_searched, none_left.found, kSmallBudget, some.frames,
                some.points_searched, some.found, e_some.centre_mm, e_some.rotation_deg, all.frames,
                all.points_searched, all.found, e_all.centre_mm, e_all.rotation_deg);
    TEST_EQUAL("a budget of one point runs one frame", none_left.frames, 1);
    TEST("  which searched its points", none_left.points_searched > 0, true);
    const PoseError e_none_left = pose_error(none_left.camera_from_model, truth, centre, {Mat33::identity()});
    TEST("  found only within 2 mm and 2 degrees (a first refining frame can pass the acceptance check)",
         !none_left.found || (e_none_left.centre_mm <= 2 && e_none_left.rotation_deg <= 2), true);
    not_found += !none_left.found;
    TEST("a small budget stops within one frame past it", some.points_searched < kSmallBudget + kOneFrameMost, true);
    TEST("  having run no more than the detection without one", some.frames <= all.frames, true);
    TEST("  found only within 2 mm and 2 degrees", !some.found || (e_some.centre_mm <= 2 && e_some.rotation_deg <= 2),
         true);
    TEST("without a budget the pose is found within 2 mm and 2 degrees",
         all.found && e_all.centre_mm <= 2 && e_all.rotation_deg <= 2, true);
    TEST("  past the small budget", all.points_searched > kSmallBudget, true);
    TEST("  not cut short", all.cut_short, false);
    TEST("cut short by the small budget", some.cut_short, true);
    TEST("  so not found", some.found, false);
    const Detection bounded = pxa270.value().detect(view).value();
    const PoseError e_bounded = pose_error(bounded.camera_from_model, truth, centre, {Mat33::identity()});
    std::printf("  budget %d: %d points, found %d cut short %d (%.3f mm %.3f deg)\n", kPxa270Budget,
                bounded.points_searched, bounded.found, bounded.cut_short, e_bounded.centre_mm, e_bounded.rotation_deg);
    TEST("the PXA270's budget finds the pose within 2 mm and 2 degrees",
         bounded.found && e_bounded.centre_mm <= 2 && e_bounded.rotation_deg <= 2, true);
    TEST("  within one frame past the budget", bounded.points_searched < kPxa270Budget + kOneFrameMost, true);
  }
  TEST("a budget of one point leaves some frames not found", not_found > 0, true);
  // The tracker of --init-auto: a first frame whose detection ran out unfound (seed 12's) is
  // lost, not detected.
  Result<TemplateSet> templates = make_template_set(model.value(), camera, oblique_range());
  TEST("templates are made", templates.ok(), true);
  if (!templates.ok()) return;
  DetectorParams params;
  params.max_points_searched = 1;
  Result<AutoInitTracker> tracker =
      AutoInitTracker::create(model.value(), camera, std::move(templates).value(), params, TrackerParams{});
  TEST("the tracker is made", tracker.ok(), true);
  if (!tracker.ok()) return;
  const Se3 truth = random_view(model.value(), camera, oblique_range().views, kSeeds[1]);
  render_trial(model.value(), camera, truth, true, kLines, kSeeds[1], frame);
  const Result<FrameResult> first =
      tracker.value().track(packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565));
  TEST("the frame is accepted", first.ok(), true);
  if (!first.ok()) return;
  TEST("a detection out of budget leaves the frame lost", first.value().status, TrackingStatus::kLost);
  TEST("  because nothing was detected", first.value().reason, StatusReason::kNotDetected);
}

TESTMAIN(test_detection_budget)
