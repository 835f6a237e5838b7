// SPDX-License-Identifier: BSD-3-Clause
/// Synthetic camera trajectories.
#include "trajectory.h"

#include <cmath>

#include "pose_table.h"

using edgetrack::Error;
using edgetrack::Result;
using edgetrack::Se3;
using edgetrack::Vec2;
using edgetrack::Vec3;

namespace edgetrack_app {

Result<std::vector<Se3>> make_trajectory(const std::string& kind, int frames) {
  if (frames <= 0) return Error{"", 0, "the number of frames must be positive"};
  std::vector<Se3> poses;
  if (kind == "paper") {
    // Set-up code in double: slow sines in the rotation vector and the translation.
    const double pi = 3.14159265358979323846;
    for (int k = 0; k < frames; ++k) {
      const double s = 2 * pi * k / 60.0;
      const double w[3] = {0.62 + 0.09 * std::sin(s), -0.66 + 0.10 * std::sin(0.5 * s + 0.4),
                           0.18 + 0.04 * std::sin(s + 1.0)};
      const double t[3] = {0.005 * std::sin(s + 0.3), 0.004 + 0.005 * std::sin(0.5 * s),
                           0.150 + 0.010 * std::sin(0.5 * s + 1.2)};
      poses.push_back(Se3(edgetrack::rotation_exp({real(w[0]), real(w[1]), real(w[2])}),
                          {real(t[0]), real(t[1]), real(t[2])}));
    }
    return poses;
  }
  auto rows = read_pose_table(kind, kTruthHeader);
  if (!rows.ok()) return rows.error();
  if (static_cast<int>(rows.value().size()) < frames)
    return Error{kind, 0, std::to_string(rows.value().size()) + " poses, fewer than the " + std::to_string(frames) +
                              " frames asked for"};
  for (int k = 0; k < frames; ++k) poses.push_back(pose_of(rows.value()[k]));
  return poses;
}

double largest_vertex_motion(const edgetrack::EdgeModel& model, const edgetrack::PinholeCamera& camera,
                             const std::vector<Se3>& poses) {
  double worst = 0;
  for (size_t k = 1; k < poses.size(); ++k)
    for (const Vec3& v : model.vertices) {
      const Vec2 a = camera.project(poses[k - 1] * v), b = camera.project(poses[k] * v);
      worst = std::fmax(worst, std::hypot(static_cast<double>(a.x - b.x), static_cast<double>(a.y - b.y)));
    }
  return worst;
}

}  // namespace edgetrack_app
