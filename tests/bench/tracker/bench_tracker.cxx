// SPDX-License-Identifier: BSD-3-Clause
/// The Table 1 benchmark: tracks the generated cube (or wood toy) sequence and prints, per
/// frame, the host time of the paper's four steps, the points sampled and matched and the
/// residual. Each Tracker::track() call is one count window for toolchains/qemu/count-insns.sh;
/// the frames are rendered before, outside the windows.
/// With "steps", the same frame loop runs from the step functions themselves, with one count
/// window per step (4 per frame, in the paper's order), for the per-step instruction shares.
///   bench_tracker [frames] [cube|toy] [steps]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "count_markers.h"
#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "visp3/core/vpImageConvert.h"

using namespace edgetrack;
using namespace edgetrack_test;

int main(int argc, char* argv[]) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : 60;
  const Scene scene = argc > 2 && std::string(argv[2]) == "toy" ? Scene::kWoodToy : Scene::kCube;
  const Result<EdgeModel> model = load_model(model_path(scene));
  if (!model.ok()) {
    std::fprintf(stderr, "%s\n", model.error().text().c_str());
    return 1;
  }
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(scene, frames);
  SceneRenderer renderer(camera, SceneStyle{});
  std::vector<Rgb565Frame> images(static_cast<size_t>(frames));
  for (int k = 0; k < frames; ++k) renderer.render(model.value(), truth[k], static_cast<uint32_t>(1000 + k), images[k]);

  if (argc > 3 && std::string(argv[3]) == "steps") {
    // Tracker::track's steps, one count window each; the pose carries over as in the tracker.
    const TrackerParams params;
    vpMe me = params.me;
    me.setSampleStep(params.sampling.step);
    EdgeIdBuffer edge_ids(camera);
    vpImage<unsigned char> grey(static_cast<unsigned>(camera.height), static_cast<unsigned>(camera.width));
    Se3 pose = truth[0];
    std::printf("# real=%s steps: 4 windows per frame (visible edges, grey, ME, pose)\n", real_name());
    for (int k = 0; k < frames; ++k) {
      edgetrack_count_begin();
      edge_ids.render(model.value(), pose);
      const std::vector<ControlPoint> visible =
          keep_visible(sample_control_points(model.value(), camera, pose, params.sampling), edge_ids);
      edgetrack_count_end();
      edgetrack_count_begin();
      vpImageConvert::RGB565ToGrey(images[k].pixels.data(), grey.bitmap, grey.getSize());
      edgetrack_count_end();
      edgetrack_count_begin();
      std::vector<EdgeMatch> matches = search_moving_edges(grey, visible, me);
      edgetrack_count_end();
      edgetrack_count_begin();
      const PoseSolution solution = solve_pose(matches, camera, pose, params.pose);
      edgetrack_count_end();
      pose = solution.camera_from_model;
      std::printf("steps %d %zu %zu\n", k, visible.size(), matches.size());
    }
    return 0;
  }

  Result<Tracker> tracker = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  if (!tracker.ok()) {
    std::fprintf(stderr, "%s\n", tracker.error().text().c_str());
    return 1;
  }
  std::printf("# real=%s scene=%s frames=%d\n", real_name(), scene == Scene::kCube ? "cube" : "toy", frames);
  std::printf("# frame visible_ns grey_ns me_ns pose_ns sampled matched outliers end_rms_px evaluations error_mm\n");
  for (int k = 0; k < frames; ++k) {
    edgetrack_count_begin();
    const FrameResult r = tracker.value().track(images[k].pixels.data());
    edgetrack_count_end();
    const Vec3 d = camera_position(r.camera_from_model) - camera_position(truth[k]);
    const double error_mm =  // in double: squares of sub-millimetre values underflow in fixed point
        1000 * std::hypot(static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z));
    std::printf("frame %d %lld %lld %lld %lld %d %d %d %.4f %d %.4f\n", k, static_cast<long long>(r.step_ns[0]),
                static_cast<long long>(r.step_ns[1]), static_cast<long long>(r.step_ns[2]),
                static_cast<long long>(r.step_ns[3]), r.points_sampled, r.points_matched, r.pose.outliers,
                static_cast<double>(r.pose.end_rms), r.pose.evaluations, error_mm);
  }
  return 0;
}
