// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack eval`: accuracy of a poses file against a ground-truth file, and the plots.
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "args.h"
#include "commands.h"
#include "evaluation.h"
#include "plots.h"

namespace edgetrack_app {

int eval_main(int argc, char** argv) {
  const CommandLine line = {
      "eval",
      "--poses FILE --truth FILE|DIR [--plots DIR] [--coverage]",
      {
          {"--poses", "FILE", "tracked poses CSV (edgetrack track --poses)", ""},
          {"--truth", "FILE|DIR", "ground truth: a CSV (edgetrack synth writes truth.csv), or a directory of one ViSP pose "
                                "file per frame, .pos or 4x4 matrix, numbered by name (Camera_001.txt: frame 1)", ""},
          {"--plots", "DIR", "directory for fig4_time_per_frame.png and fig5_camera_position.png", ""},
          {"--coverage", "", "evaluate a poses file that covers only part of the truth, and say how much", ""},
      },
      {"--poses", "--truth"},
      {},
      {},
  };
  Args a;
  if (auto stop = parse_command_line(line, argc, argv, a)) return *stop;
  auto poses = read_pose_table(a.text("--poses"), kPosesHeader);
  if (!poses.ok()) return report("eval", poses.error());
  auto truth = read_truth(a.text("--truth"));
  if (!truth.ok()) return report("eval", truth.error());
  auto evaluation = evaluate(poses.value(), truth.value(), a.text("--truth"));
  if (!evaluation.ok()) return report("eval", evaluation.error());
  const Evaluation& e = evaluation.value();
  if (e.first_missing >= 0 && !a.has("--coverage"))
    return report("eval", {a.text("--poses"), 0,
                           "covers " + std::to_string(e.frames.size()) + " of the " + std::to_string(e.truth_frames) +
                               " frames of " + a.text("--truth") + " (frame " + std::to_string(e.first_missing) +
                               " is missing): a run that stopped early? --coverage evaluates what is there"});
  if (e.first_missing >= 0)
    std::printf("coverage: %zu of %d truth frames tracked (first missing: %d)\n", e.frames.size(), e.truth_frames,
                e.first_missing);
  std::printf("frames %zu, lost %d\n", e.frames.size(), e.lost);
  std::printf("mean absolute camera position error: x %.2f mm, y %.2f mm, z %.2f mm\n", e.mean_abs_mm[0],
              e.mean_abs_mm[1], e.mean_abs_mm[2]);
  std::printf("mean distance to ground truth: %.2f mm (largest %.2f mm)\n", e.mean_distance_mm, e.max_distance_mm);
  std::printf("mean rotation error: %.3f deg\n", e.mean_rotation_deg);
  std::printf("mean tracking time: %.2f ms per frame\n", e.mean_ms);
  // One line of key=value for scripts and tests.
  std::printf("eval: frames=%zu lost=%d x_mm=%.4f y_mm=%.4f z_mm=%.4f distance_mm=%.4f max_distance_mm=%.4f rotation_deg=%.4f\n",
              e.frames.size(), e.lost, e.mean_abs_mm[0], e.mean_abs_mm[1], e.mean_abs_mm[2], e.mean_distance_mm,
              e.max_distance_mm, e.mean_rotation_deg);
  if (a.has("--plots")) {
    const std::string dir = a.text("--plots");
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) return report("eval", {dir, 0, "cannot create the directory: " + error.message()});
    auto written = write_plots(dir, e);
    if (!written.ok()) return report("eval", written.error());
    std::printf("plots: %s/fig4_time_per_frame.png %s/fig5_camera_position.png\n", dir.c_str(), dir.c_str());
  }
  return 0;
}

}  // namespace edgetrack_app
