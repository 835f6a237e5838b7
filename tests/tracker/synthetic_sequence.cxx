// SPDX-License-Identifier: BSD-3-Clause
/// The synthetic sequences' camera, models and true poses (edgetrack/synthetic_trajectory.h).
#include "synthetic_sequence.h"

using namespace edgetrack;

namespace edgetrack_test {

// The paper fixes the cube (60 mm), its distance (about 150 mm), QVGA and "around 60 points"
// but not the focal length; px = py = 220 (a 72 degree horizontal field of view, as wide-angle
// phone and SD-card cameras of the time had) gives the cube's 9 visible edges about 63 control
// points per frame, where 300 gave 83.
PinholeCamera qvga_camera() { return {real(220), real(220), real(160), real(120), 320, 240}; }

std::string model_path(Scene scene) {
  const char* name = scene == Scene::kCube ? "/models/cube60.cao"
                     : scene == Scene::kWoodToy ? "/models/wood_toy.cao"
                                                : "/models/cube60_cylinder.cao";
  return std::string(EDGETRACK_DATA_DIR) + name;
}

std::vector<Se3> true_poses(Scene scene, int frames, int subsample) {
  const std::vector<Se3> path =
      scene == Scene::kWoodToy ? wood_toy_trajectory(frames * subsample) : cube_trajectory(frames * subsample);
  std::vector<Se3> poses;
  for (int k = 0; k < frames; ++k) poses.push_back(path[static_cast<size_t>(k * subsample)]);
  return poses;
}

Vec3 camera_position(const Se3& camera_from_model) { return camera_from_model.inverse().translation(); }

}  // namespace edgetrack_test
