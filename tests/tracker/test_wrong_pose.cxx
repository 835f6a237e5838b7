// SPDX-License-Identifier: BSD-3-Clause
/// A wrong detection is found out (docs/ARCHITECTURE.md, "Tracking status"): the generated cube
/// tracked from a start the detector could give, the cube farther along the ray through its
/// nearest corner (that corner and the edges from it where the true ones are, the rest of its
/// outline over the cube's flat faces), is never reported tracked while it is off: the image
/// supports under confirm_support_share of its outline; the true pose given as a detection is
/// confirmed and tracked, its outline supported over 0.8 at a few degrees. The wrong start fits
/// its matches at 2-5 px, which the loose-fit bound alone calls uncertain; with the bounds that
/// see a loose fit opened past it, only the support rule refuses it, and it must.
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

constexpr int kFrames = 8;

/// The statuses of kFrames frames of the cube tracked from `start` given as a detection.
std::vector<FrameResult> track_from(const EdgeModel& model, const Se3& start, const TrackerParams& params) {
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(Scene::kCube, kFrames);
  SceneRenderer renderer(camera, SceneStyle{});
  Result<Tracker> tracker = Tracker::create(model, camera, start, params);
  std::vector<FrameResult> results;
  if (!tracker.ok() || !tracker.value().reset(start, Tracker::StartPose::kDetected)) return results;
  Rgb565Frame frame;
  for (int k = 0; k < kFrames; ++k) {
    renderer.render(model, truth[static_cast<size_t>(k)], static_cast<uint32_t>(k + 1), frame);
    const Result<FrameResult> result = tracker.value().track(rgb565_view(frame));
    if (!result.ok()) break;
    results.push_back(result.value());
  }
  return results;
}

/// The settings under which only the image's support can refuse the wrong start: a residual
/// scale and a pose uncertainty up to 5 px count as tracked (an approximate model's), and
/// residuals are at chance only past 5 px, so the support is judged at every frame.
TrackerParams loose_fit_accepted() {
  TrackerParams params;
  params.status.tracked_scale_px = real(5);
  params.status.lost_scale_floor_px = real(5);
  params.status.max_pose_uncertainty_px = real(5);
  params.status.lost_uncertainty_range_share = real(2);
  return params;
}

int tracked(const std::vector<FrameResult>& results) {
  int n = 0;
  for (const FrameResult& r : results) n += r.status == TrackingStatus::kTracked;
  return n;
}

/// The true start is tracked and supported; the wrong one `beside` is never reported tracked
/// while it is off, nor supported as a confirmed detection needs.
void check_wrong_start(const EdgeModel& model, const Se3& truth, const Se3& beside, const TrackerParams& params) {
  const std::vector<FrameResult> right = track_from(model, truth, params);
  TEST_EQUAL("from the true pose as a detection every frame is tracked", tracked(right), kFrames);
  TEST("its edges have image gradient along them", right.size() == kFrames && right[1].measures.support_share > real(0.8),
       true);
  TEST("at a few degrees from their normals", right.size() == kFrames && right[1].measures.gradient_angle_deg < real(10),
       true);
  const std::vector<FrameResult> wrong = track_from(model, beside, params);
  TEST_EQUAL("all frames run from the wrong start", wrong.size(), size_t(kFrames));
  const std::vector<Se3> poses = true_poses(Scene::kCube, kFrames);
  int off = 0, tracked_off = 0, supported_off = 0;
  for (size_t k = 0; k < wrong.size(); ++k) {
    const real error_mm = real(1000) * norm(wrong[k].pose.camera_from_model.translation() - poses[k].translation());
    if (error_mm <= real(5)) continue;
    ++off;
    tracked_off += wrong[k].status == TrackingStatus::kTracked;
    supported_off += wrong[k].measures.support_share >= params.status.confirm_support_share;
  }
  TEST("the wrong start is off on its first frames", off > 0, true);
  TEST_EQUAL("no frame more than 5 mm off is reported tracked", tracked_off, 0);
  TEST_EQUAL("the image supports none of them as a confirmed detection needs", supported_off, 0);
}

}  // namespace

static void test_wrong_pose() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the cube loads", model.ok(), true);
  if (!model.ok()) return;
  const Se3 truth = true_poses(Scene::kCube, 1)[0];
  // The corner nearest the camera, and the cube 30 % farther along the ray through it.
  Vec3 nearest = truth * model.value().vertices[0];
  for (const Vec3& v : model.value().vertices) {
    const Vec3 c = truth * v;
    if (c.z < nearest.z) nearest = c;
  }
  const Se3 beside(truth.rotation(), truth.translation() + real(0.3) * nearest);
  for (const TrackerParams& params : {TrackerParams{}, loose_fit_accepted()}) {
    const bool loose = params.status.tracked_scale_px > TrackerParams{}.status.tracked_scale_px;
    std::printf("%s\n", loose ? "With a fit up to 5 px accepted, so that only the support rule can refuse the wrong start:"
                              : "With the default settings:");
    check_wrong_start(model.value(), truth, beside, params);
  }
}

TESTMAIN(test_wrong_pose)
