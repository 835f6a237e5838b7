// SPDX-License-Identifier: BSD-3-Clause
/// Accuracy of tracked poses against ground truth, as the paper reports it (section 4): the
/// camera position in the object frame, per axis and as a distance, plus the rotation error.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/result.h"
#include "pose_table.h"

namespace edgetrack_app {

struct FrameError {
  int frame = 0;
  double position[3] = {0, 0, 0};        ///< tracked camera position in the object frame, mm
  double true_position[3] = {0, 0, 0};   ///< ground truth, mm
  double distance_mm = 0;                ///< |position - true_position|
  double rotation_deg = 0;               ///< angle of R_tracked * R_true^T
  double ms = 0;
  bool lost = false;
};

struct Evaluation {
  std::vector<FrameError> frames;
  double mean_abs_mm[3] = {0, 0, 0};  ///< x, y, z
  double mean_distance_mm = 0;
  double max_distance_mm = 0;
  double mean_rotation_deg = 0;
  double mean_ms = 0;
  int lost = 0;
  int truth_frames = 0;  ///< rows of the ground truth; frames.size() of them were tracked
  int first_missing = -1;  ///< the first truth frame without a tracked pose, or -1
};

/// Compares every tracked frame with the truth row of the same frame number; a tracked frame
/// without truth is an error naming `truth_path`. Truth frames without a tracked pose are
/// counted (truth_frames, first_missing), not refused: the caller decides.
edgetrack::Result<Evaluation> evaluate(const std::vector<PoseRow>& poses, const std::vector<PoseRow>& truth,
                                       const std::string& truth_path);

}  // namespace edgetrack_app
