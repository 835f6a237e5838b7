// SPDX-License-Identifier: BSD-3-Clause
/// Synthetic camera trajectories.
#include "trajectory.h"

#include "pose_table.h"

using edgetrack::Error;
using edgetrack::Result;
using edgetrack::Se3;

namespace edgetrack_app {

Result<std::vector<Se3>> make_trajectory(const std::string& kind, int frames) {
  if (frames <= 0) return Error{"", 0, "the number of frames must be positive"};
  if (kind == "paper") return edgetrack::cube_trajectory(frames);
  auto rows = read_pose_table(kind, kTruthHeader);
  if (!rows.ok()) return rows.error();
  if (static_cast<int>(rows.value().size()) < frames)
    return Error{kind, 0, std::to_string(rows.value().size()) + " poses, fewer than the " + std::to_string(frames) +
                              " frames asked for"};
  std::vector<Se3> poses;
  for (int k = 0; k < frames; ++k) poses.push_back(pose_of(rows.value()[k]));
  return poses;
}

}  // namespace edgetrack_app
