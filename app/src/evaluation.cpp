// SPDX-License-Identifier: BSD-3-Clause
/// Position and rotation errors of tracked poses against ground truth.
#include "evaluation.h"

#include <cmath>
#include <map>

#include "edgetrack/angles.h"

using edgetrack::Error;
using edgetrack::Result;
using edgetrack::Se3;
using edgetrack::Vec3;

namespace edgetrack_app {

Result<Evaluation> evaluate(const std::vector<PoseRow>& poses, const std::vector<PoseRow>& truth,
                            const std::string& truth_path) {
  std::map<int, const PoseRow*> truth_of;
  for (const PoseRow& row : truth) truth_of[row.frame] = &row;
  Evaluation result;
  for (const PoseRow& row : poses) {
    const auto found = truth_of.find(row.frame);
    if (found == truth_of.end()) return Error{truth_path, 0, "no ground truth for frame " + std::to_string(row.frame)};
    const Se3 tracked = pose_of(row), true_pose = pose_of(*found->second);
    const Vec3 c = tracked.inverse().translation(), c_true = true_pose.inverse().translation();
    FrameError e;
    e.frame = row.frame;
    const double p[3] = {static_cast<double>(c.x), static_cast<double>(c.y), static_cast<double>(c.z)};
    const double q[3] = {static_cast<double>(c_true.x), static_cast<double>(c_true.y), static_cast<double>(c_true.z)};
    double squared = 0;
    for (int i = 0; i < 3; ++i) {
      e.position[i] = 1000 * p[i];
      e.true_position[i] = 1000 * q[i];
      result.mean_abs_mm[i] += std::fabs(e.position[i] - e.true_position[i]);
      squared += (e.position[i] - e.true_position[i]) * (e.position[i] - e.true_position[i]);
    }
    e.distance_mm = std::sqrt(squared);
    const Vec3 w = edgetrack::rotation_log(tracked.rotation() * true_pose.rotation().transpose());
    e.rotation_deg = static_cast<double>(edgetrack::norm(w)) * 180.0 / edgetrack::kPi;
    e.ms = row.ms;
    e.lost = row.lost;
    result.mean_distance_mm += e.distance_mm;
    result.max_distance_mm = std::fmax(result.max_distance_mm, e.distance_mm);
    result.mean_rotation_deg += e.rotation_deg;
    result.mean_ms += e.ms;
    result.lost += e.lost ? 1 : 0;
    result.frames.push_back(e);
  }
  result.truth_frames = static_cast<int>(truth.size());
  std::map<int, bool> tracked;
  for (const PoseRow& row : poses) tracked[row.frame] = true;
  for (const PoseRow& row : truth)
    if (!tracked.count(row.frame)) {
      result.first_missing = row.frame;
      break;
    }
  const double n = result.frames.empty() ? 1.0 : static_cast<double>(result.frames.size());
  for (double& m : result.mean_abs_mm) m /= n;
  result.mean_distance_mm /= n;
  result.mean_rotation_deg /= n;
  result.mean_ms /= n;
  return result;
}

}  // namespace edgetrack_app
