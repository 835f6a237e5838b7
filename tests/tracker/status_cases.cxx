// SPDX-License-Identifier: BSD-3-Clause
/// The tracking-status cases and what a run of one did.
#include "status_cases.h"

#include <cmath>

#include "edgetrack/model_io.h"

using namespace edgetrack;

namespace edgetrack_test {
namespace {

StatusCase interrupted(const std::string& name, FrameContent content, int first, int end) {
  StatusCase c;
  c.name = name;
  c.frames = 30;
  c.spec.content.assign(static_cast<size_t>(c.frames), FrameContent::kScene);
  for (int k = first; k < end; ++k) c.spec.content[static_cast<size_t>(k)] = content;
  c.first_bad = first;
  c.visible_again = end;
  c.wholly_in_view = first;
  return c;
}

/// From the cube's first pose, the camera accelerates sideways to 6 mm (about 9 px) per frame
/// until the cube has left the image.
StatusCase leaving_view() {
  StatusCase c;
  c.name = "leaving the view";
  c.frames = 40;
  const Se3 start = true_poses(Scene::kCube, 1)[0];
  double x = 0;
  for (int k = 0; k < c.frames; ++k) {
    x += 0.0005 * std::fmin(k, 12);
    c.spec.poses.push_back(Se3(start.rotation(), start.translation() + Vec3{real(x), real(0), real(0)}));
  }
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  const PinholeCamera camera = qvga_camera();
  const SamplingParams sampling;
  c.first_bad = c.visible_again = c.frames;
  for (int k = 0; k < c.frames && model.ok(); ++k) {
    bool whole = true;
    for (const Vec3& v : model.value().vertices) {
      const Vec2 p = camera.project(c.spec.poses[static_cast<size_t>(k)] * v);
      whole = whole && p.x >= real(sampling.border) && p.x <= real(camera.width - 1 - sampling.border);
    }
    if (whole && k == c.wholly_in_view) ++c.wholly_in_view;
    const size_t left = sample_control_points(model.value(), camera, c.spec.poses[static_cast<size_t>(k)], sampling).size();
    if (static_cast<int>(left) < PoseParams{}.min_points && c.first_bad == c.frames) c.first_bad = k;
  }
  return c;
}

/// The farthest a cube vertex inside the QVGA image at `truth` is drawn from there by `drawn`, px.
double overlay_offset_px(const Se3& drawn, const Se3& truth) {
  static const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  const PinholeCamera camera = qvga_camera();
  double worst = 0;
  for (const Vec3& v : model.value().vertices) {
    const Vec2 at = camera.project(truth * v);
    if (at.x < real(0) || at.y < real(0) || at.x > real(camera.width - 1) || at.y > real(camera.height - 1)) continue;
    worst = std::fmax(worst, static_cast<double>(norm(camera.project(drawn * v) - at)));
  }
  return worst;
}

}  // namespace

std::vector<StatusCase> status_cases() {
  return {interrupted("noise at 10-11", FrameContent::kNoise, 10, 12),
          interrupted("flat at 10-11", FrameContent::kFlat, 10, 12),
          interrupted("covered at 12-14", FrameContent::kNoObject, 12, 15), leaving_view()};
}

StatusOutcome status_outcome(const StatusCase& c, const SequenceRun& run) {
  StatusOutcome o;
  const int frames = static_cast<int>(run.frames.size());
  for (int k = 0; k < frames; ++k) {
    const FrameResult& frame = run.frames[static_cast<size_t>(k)];
    const bool lost = frame.status == TrackingStatus::kLost;
    o.lost += lost;
    o.uncertain += frame.status == TrackingStatus::kUncertain;
    if (frame.status == TrackingStatus::kTracked)
      o.worst_tracked_px =
          std::fmax(o.worst_tracked_px, overlay_offset_px(frame.camera_from_model, run.truth[static_cast<size_t>(k)]));
    if (lost && o.first_lost < 0) o.first_lost = k;
    if (k >= c.first_bad && k < c.visible_again) o.missed += !lost;
    else if (k < c.wholly_in_view || k >= c.visible_again) o.wrongly_lost += lost;
  }
  for (int k = c.visible_again; k < frames && o.back < 0; ++k)
    if (run.frames[static_cast<size_t>(k)].status == TrackingStatus::kTracked && run.position_error_mm[static_cast<size_t>(k)] < 1.0)
      o.back = k;
  for (int k = o.back; o.back >= 0 && k < frames; ++k)
    o.worst_after_back_mm = std::fmax(o.worst_after_back_mm, run.position_error_mm[static_cast<size_t>(k)]);
  return o;
}

}  // namespace edgetrack_test
