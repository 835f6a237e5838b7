// SPDX-License-Identifier: BSD-3-Clause
/// The Table 1 benchmark: tracks the generated cube (or wood toy) sequence and prints, per
/// frame, the host time of the paper's four steps, the points sampled and matched and the
/// residual. Each Tracker::track() call is one count window for toolchains/qemu/count-insns.sh;
/// the frames are rendered before, outside the windows. With "steps", a StepObserver opens one
/// window per step of Tracker::track instead (4 per frame, in the paper's order). "whole" makes
/// the grey step convert whole frames (the paper's way) instead of on demand.
/// "normal" solves the pose on the 6 x 6 normal equations (PoseSolver::kNormalEquations); a
/// ViSP XML file applies its tracker settings (step, range, masks, faces) to the sequence's camera
/// ("-": none); a kud renders the frames through ViSP's radial lens and gives the tracker the lens.
///   bench_tracker [frames] [cube|toy] [frame|steps] [on-demand|whole] [hypotheses] [lmder|normal] [visp.xml|-] [kud]
/// With EDGETRACK_KERNELS=scalar in the environment it runs the scalar reference kernels
/// (real/vector_kernels.h), to count what the vector ones save.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "count_markers.h"
#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "edgetrack/visp_config.h"
#include "real/vector_kernels.h"
#include "synthetic_sequence.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// One count window per step.
class CountEachStep : public StepObserver {
 public:
  void begin(Step) override { edgetrack_count_begin(); }
  void end(Step) override { edgetrack_count_end(); }
};

}  // namespace

int main(int argc, char* argv[]) {
  const char* kernels = std::getenv("EDGETRACK_KERNELS");
  if (kernels && std::string(kernels) == "scalar") vector_kernels::choose(vector_kernels::Choice::kScalar);
  const int frames = argc > 1 ? std::atoi(argv[1]) : 60;
  const Scene scene = argc > 2 && std::string(argv[2]) == "toy" ? Scene::kWoodToy : Scene::kCube;
  const Result<EdgeModel> model = load_model(model_path(scene));
  if (!model.ok()) {
    std::fprintf(stderr, "%s\n", model.error().text().c_str());
    return 1;
  }
  PinholeCamera camera = qvga_camera();
  if (argc > 8) {
    camera.lens.model = LensModel::kVisp;
    camera.lens.kud = real(std::atof(argv[8]));
  }
  const std::vector<Se3> truth = true_poses(scene, frames);
  SceneRenderer renderer(camera, SceneStyle{});
  std::vector<Rgb565Frame> images(static_cast<size_t>(frames));
  for (int k = 0; k < frames; ++k) renderer.render(model.value(), truth[k], static_cast<uint32_t>(1000 + k), images[k]);

  const std::string windows = argc > 3 ? argv[3] : "frame", grey = argc > 4 ? argv[4] : "on-demand";
  if ((windows != "frame" && windows != "steps") || (grey != "on-demand" && grey != "whole")) {
    std::fprintf(stderr, "usage: bench_tracker [frames] [cube|toy] [frame|steps] [on-demand|whole] [hypotheses] [lmder|normal] [visp.xml|-] [kud]\n");
    return 2;
  }
  const bool per_step = windows == "steps", whole = grey == "whole";
  TrackerParams params;
  params.grey = whole ? GreyScaling::kWholeFrame : GreyScaling::kOnDemand;
  if (argc > 5) params.hypotheses = std::atoi(argv[5]);
  const std::string solver = argc > 6 ? argv[6] : "lmder";
  if (solver != "lmder" && solver != "normal") {
    std::fprintf(stderr, "bench_tracker: the solver is lmder or normal, not %s\n", solver.c_str());
    return 2;
  }
  if (solver == "normal") params.pose.solver = PoseSolver::kNormalEquations;
  if (argc > 7 && std::string(argv[7]) != "-") {  // a ViSP configuration's tracker settings, on the sequence's own camera
    TrackerConfig config;
    config.params = params;
    const Result<ConfigNotes> applied = apply_visp_config(argv[7], config);
    if (!applied.ok()) {
      std::fprintf(stderr, "%s\n", applied.error().text().c_str());
      return 1;
    }
    params = config.params;
  }
  Result<Tracker> tracker = Tracker::create(model.value(), camera, truth[0], params);
  if (!tracker.ok()) {
    std::fprintf(stderr, "%s\n", tracker.error().text().c_str());
    return 1;
  }
  CountEachStep count_each_step;
  if (per_step) tracker.value().set_step_observer(&count_each_step);
  std::printf(
      "# real=%s scene=%s frames=%d grey=%s windows=%s camera=%dx%d px=%g py=%g robust_rounds=%d "
      "robust_evaluations=%d hypotheses=%d solver=%s sample_step=%g range=%u\n",
              real_name(), scene == Scene::kCube ? "cube" : "toy", frames, grey.c_str(),
              per_step ? "4 per frame (visible edges, grey, ME, pose)" : "1 per frame", camera.width, camera.height,
              static_cast<double>(camera.px), static_cast<double>(camera.py), params.pose.robust_rounds,
              params.pose.robust_evaluations, params.hypotheses, solver.c_str(),
              static_cast<double>(params.me.sample_step), params.me.range);
  std::printf(
      "# frame visible_ns grey_ns me_ns pose_ns sampled matched outliers end_rms_px evaluations error_mm grey_pixels jacobians\n");
  for (int k = 0; k < frames; ++k) {
    if (!per_step) edgetrack_count_begin();
    const FrameResult r = tracker.value().track(rgb565_view(images[k])).value();
    if (!per_step) edgetrack_count_end();
    const Vec3 d = camera_position(r.camera_from_model) - camera_position(truth[k]);
    const double error_mm =  // in double: squares of sub-millimetre values underflow in fixed point
        1000 * std::hypot(static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z));
    std::printf("frame %d %lld %lld %lld %lld %d %d %d %.4f %d %.4f %u %d\n", k, static_cast<long long>(r.step_ns[0]),
                static_cast<long long>(r.step_ns[1]), static_cast<long long>(r.step_ns[2]),
                static_cast<long long>(r.step_ns[3]), r.points_sampled, r.points_matched, r.pose.outliers,
                static_cast<double>(r.pose.end_rms), r.pose.evaluations, error_mm, r.grey_pixels,
                r.pose.iterations);
  }
  return 0;
}
