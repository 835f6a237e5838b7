// SPDX-License-Identifier: BSD-3-Clause
/// Trajectories of the synthetic sequences: sums of slow sines, so the motion is smooth.
#include "synthetic_sequence.h"

#include <cmath>

using namespace edgetrack;

namespace edgetrack_test {

PinholeCamera qvga_camera() { return {real(300), real(300), real(160), real(120), 320, 240}; }

std::string model_path(Scene scene) {
  return std::string(EDGETRACK_DATA_DIR) + (scene == Scene::kCube ? "/models/cube60.cao" : "/models/wood_toy.cao");
}

std::vector<Se3> true_poses(Scene scene, int frames) {
  // Set-up code: the trajectory is computed in double and converted once per frame.
  const double pi = 3.14159265358979323846;
  std::vector<Se3> poses;
  for (int k = 0; k < frames; ++k) {
    const double s = 2 * pi * k / 60.0;
    double w[3], t[3];
    if (scene == Scene::kCube) {
      // Three faces in view, 150 mm away, swaying and turning.
      w[0] = 0.55 + 0.08 * std::sin(s);
      w[1] = -0.60 + 0.09 * std::sin(0.5 * s + 0.4);
      w[2] = 0.15 + 0.04 * std::sin(s + 1.0);
      t[0] = 0.005 * std::sin(s + 0.3);
      t[1] = 0.006 + 0.004 * std::sin(0.5 * s);
      t[2] = 0.150 + 0.010 * std::sin(0.5 * s + 1.2);
    } else {
      // Seen from above and one side, turning so that the tower sweeps over the base.
      w[0] = -2.10 + 0.15 * std::sin(0.5 * s);
      w[1] = 0.0 + 0.15 * std::sin(s + 0.5);
      w[2] = 0.20 + 0.40 * std::sin(0.5 * s - 0.6);
      t[0] = 0.008 * std::sin(s);
      t[1] = 0.004 * std::sin(0.5 * s + 0.7);
      t[2] = 0.200 + 0.010 * std::sin(0.5 * s);
    }
    poses.push_back(Se3(rotation_exp({real(w[0]), real(w[1]), real(w[2])}), {real(t[0]), real(t[1]), real(t[2])}));
  }
  return poses;
}

Vec3 camera_position(const Se3& camera_from_model) { return camera_from_model.inverse().translation(); }

double largest_vertex_motion(const EdgeModel& model, const PinholeCamera& camera, const std::vector<Se3>& poses) {
  double worst = 0;
  for (size_t k = 1; k < poses.size(); ++k)
    for (const Vec3& v : model.vertices) {
      const Vec2 a = camera.project(poses[k - 1] * v), b = camera.project(poses[k] * v);
      worst = std::fmax(worst, std::hypot(static_cast<double>(a.x - b.x), static_cast<double>(a.y - b.y)));
    }
  return worst;
}

}  // namespace edgetrack_test
