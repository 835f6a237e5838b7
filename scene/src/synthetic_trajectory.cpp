// SPDX-License-Identifier: BSD-3-Clause
/// Synthetic camera trajectories: sums of slow sines in the rotation vector and the translation.
#include "edgetrack/synthetic_trajectory.h"

#include <cmath>

#include "edgetrack/angles.h"

namespace edgetrack {
namespace {

/// Set-up code: the trajectory is computed in double and converted once per frame.
Se3 pose_from(const double w[3], const double t[3]) {
  return Se3(rotation_exp({real(w[0]), real(w[1]), real(w[2])}), {real(t[0]), real(t[1]), real(t[2])});
}


}  // namespace

std::vector<Se3> cube_trajectory(int frames) {
  std::vector<Se3> poses;
  for (int k = 0; k < frames; ++k) {
    const double s = 2 * kPi * k / 60.0;
    const double w[3] = {0.55 + 0.11 * std::sin(s), -0.60 + 0.12 * std::sin(0.5 * s + 0.4),
                         0.15 + 0.055 * std::sin(s + 1.0)};
    const double t[3] = {0.007 * std::sin(s + 0.3), 0.006 + 0.0055 * std::sin(0.5 * s),
                         0.150 + 0.013 * std::sin(0.5 * s + 1.2)};
    poses.push_back(pose_from(w, t));
  }
  return poses;
}

std::vector<Se3> wood_toy_trajectory(int frames) {
  std::vector<Se3> poses;
  for (int k = 0; k < frames; ++k) {
    const double s = 2 * kPi * k / 60.0;
    const double w[3] = {-2.10 + 0.15 * std::sin(0.5 * s), 0.15 * std::sin(s + 0.5), 0.20 + 0.40 * std::sin(0.5 * s - 0.6)};
    const double t[3] = {0.008 * std::sin(s), 0.004 * std::sin(0.5 * s + 0.7), 0.150 + 0.0075 * std::sin(0.5 * s)};
    poses.push_back(pose_from(w, t));
  }
  return poses;
}

double largest_vertex_motion(const EdgeModel& model, const PinholeCamera& camera, const std::vector<Se3>& poses) {
  double worst = 0;
  for (size_t k = 1; k < poses.size(); ++k)
    for (const Vec3& v : model.vertices) {
      const Vec2 a = camera.project(poses[k - 1] * v), b = camera.project(poses[k] * v);
      worst = std::fmax(worst, std::hypot(static_cast<double>(a.x - b.x), static_cast<double>(a.y - b.y)));
    }
  return worst;
}

}  // namespace edgetrack
