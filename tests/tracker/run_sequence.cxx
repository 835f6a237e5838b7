// SPDX-License-Identifier: BSD-3-Clause
/// The sequence runner shared by the tracking tests, the golden-file writer and the benchmark.
#include "run_sequence.h"

#include <cmath>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_extras.h"
#include "edgetrack/scene_renderer.h"
#include "rolling_shutter_render.h"

using namespace edgetrack;

namespace edgetrack_test {
namespace {

bool hidden_by_more_than_a_pixel(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                                 const Vec3& point_in_model, const real& margin) {
  const Se3 model_from_camera = camera_from_model.inverse();
  const Vec3 p = camera_from_model * point_in_model;
  const real dx = p.z / camera.px, dy = p.z / camera.py;
  const Vec3 shifts[5] = {{real(0), real(0), real(0)}, {dx, real(0), real(0)}, {-dx, real(0), real(0)},
                          {real(0), dy, real(0)}, {real(0), -dy, real(0)}};
  for (const Vec3& shift : shifts)
    if (point_visible(model, camera_from_model, model_from_camera * (p + shift), margin)) return false;
  return true;
}

/// Replaces the frame's pixels with uniform noise or one flat grey.
void fill(FrameContent content, uint32_t seed, Rgb565Frame& frame) {
  uint32_t state = seed * 2654435761u + 1;
  for (uint16_t& pixel : frame.pixels) {
    unsigned grey = 128;
    if (content == FrameContent::kNoise) {
      state ^= state << 13;  // xorshift32
      state ^= state >> 17;
      state ^= state << 5;
      grey = state >> 24;
    }
    pixel = static_cast<uint16_t>(((grey >> 3) << 11) | ((grey >> 2) << 5) | (grey >> 3));
  }
}

}  // namespace

int count_status(const SequenceRun& run, TrackingStatus status) {
  int n = 0;
  for (const FrameResult& f : run.frames) n += f.status == status;
  return n;
}

SequenceRun run_sequence(Scene scene, int frames, bool visibility_check, const TrackerParams& params,
                         const SequenceSpec& spec) {
  SequenceRun run;
  const Result<EdgeModel> model = load_model(model_path(scene));
  if (!model.ok()) return run;
  PinholeCamera lens_camera = qvga_camera();
  lens_camera.lens = spec.lens;
  const PinholeCamera camera = spec.lens_given ? lens_camera : lens_camera.pinhole();
  run.truth = spec.poses.empty() ? true_poses(scene, frames, spec.subsample) : spec.poses;
  if (static_cast<int>(run.truth.size()) != frames) return run;
  const EdgeModel nothing;
  Result<Tracker> tracker = Tracker::create(model.value(), camera, run.truth[0], params);
  if (!tracker.ok()) return run;
  run.loaded = true;
  SceneRenderer renderer(lens_camera, SceneStyle{});
  Rgb565Frame frame;
  const std::vector<Segment3> clutter = parallel_clutter(model.value(), real(spec.clutter));
  SceneAdditions additions;
  if (spec.clutter > 0) additions.clutter = &clutter;
  std::vector<uint8_t> mask;
  std::vector<int> columns;
  const real margin = real(0.02);
  double error_sum = 0, points_sum = 0;
  for (int k = 0; k < frames; ++k) {
    const FrameContent content = k < static_cast<int>(spec.content.size()) ? spec.content[k] : FrameContent::kScene;
    if (spec.cover > 0) {
      silhouette_columns(model.value(), camera, run.truth[k], mask, columns);
      additions.band = occluder_band(columns, sweeping_centre(columns, k, frames), real(spec.cover));
    }
    if (spec.readout != 0)
      render_rolling_shutter(renderer, model.value(), run.truth, k, spec.readout, spec.readout_renders,
                             static_cast<uint32_t>(1000 + k), frame);
    else
      renderer.render(content == FrameContent::kNoObject ? nothing : model.value(), run.truth[k],
                      static_cast<uint32_t>(1000 + k), additions, frame);
    if (content == FrameContent::kNoise || content == FrameContent::kFlat) fill(content, static_cast<uint32_t>(k), frame);
    const Se3 sampling_pose = tracker.value().camera_from_model();
    const FrameResult result = tracker.value().track(rgb565_view(frame)).value();
    run.frames.push_back(result);
    const Vec3 d = camera_position(result.camera_from_model) - camera_position(run.truth[k]);
    const double error_mm =
        1000 * std::sqrt(static_cast<double>(d.x) * static_cast<double>(d.x) +
                         static_cast<double>(d.y) * static_cast<double>(d.y) + static_cast<double>(d.z) * static_cast<double>(d.z));
    run.position_error_mm.push_back(error_mm);
    error_sum += error_mm;
    points_sum += result.points_sampled;
    run.outliers += result.pose.outliers;
    std::vector<int> matched(static_cast<size_t>(primitive_count(model.value())), 0);
    for (const EdgeMatch& m : tracker.value().matches()) matched[static_cast<size_t>(m.point.edge)] += !m.outlier;
    run.matched_per_primitive.push_back(matched);
    if (visibility_check) {
      for (const ControlPoint& p : tracker.value().control_points())
        run.hidden_points_sampled +=
            hidden_by_more_than_a_pixel(model.value(), camera, sampling_pose, p.point_in_model, margin);
      if (k % 4 == 0)  // every fourth frame is enough to show that hidden candidates exist
        for (const ControlPoint& p : sample_control_points(model.value(), camera, sampling_pose, SamplingParams{}))
          run.hidden_points_dropped +=
              hidden_by_more_than_a_pixel(model.value(), camera, sampling_pose, p.point_in_model, margin);
    }
  }
  run.mean_position_error_mm = error_sum / frames;
  run.mean_points_sampled = points_sum / frames;
  return run;
}

}  // namespace edgetrack_test
