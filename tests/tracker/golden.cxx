// SPDX-License-Identifier: BSD-3-Clause
/// Reading and writing the tracking tests' golden files.
#include "golden.h"

#include <cstdio>
#include <fstream>

#include "edgetrack/scene_extras.h"

using namespace edgetrack;

namespace edgetrack_test {

std::string golden_name(Scene scene, int subsample, int hypotheses) {
  std::string speed = subsample > 1 ? "_fast" + std::to_string(subsample) : "";
  if (hypotheses != edgetrack::TrackerParams{}.hypotheses) speed += "_k" + std::to_string(hypotheses);
  const char* base = scene == Scene::kCube ? "cube60" : scene == Scene::kWoodToy ? "wood_toy" : "cube60_cylinder";
  return base + speed + "_double_positions.txt";
}

SequenceSpec covered_spec() {
  SequenceSpec spec;
  spec.cover = kCoveredShare;
  return spec;
}

std::string covered_golden_name(Scene scene) {
  return std::string(scene == Scene::kCube ? "cube60" : scene == Scene::kWoodToy ? "wood_toy" : "cube60_cylinder") +
         "_cover30_double_positions.txt";
}

SequenceSpec reversal_spec(Scene scene) {
  SequenceSpec spec;
  spec.poses = there_and_back(true_poses(scene, kReversalTurn + 1, kFastSpeedUp));
  return spec;
}

std::string reversal_golden_name(Scene scene) {
  return std::string(scene == Scene::kCube ? "cube60" : scene == Scene::kWoodToy ? "wood_toy" : "cube60_cylinder") +
         "_reverse" + std::to_string(kFastSpeedUp) + "_double_positions.txt";
}

bool write_golden(const std::string& path, const SequenceRun& run) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return false;
  for (const FrameResult& frame : run.frames) {
    const Vec3 c = camera_position(frame.camera_from_model);
    std::fprintf(file, "%.9f %.9f %.9f\n", static_cast<double>(c.x), static_cast<double>(c.y),
                 static_cast<double>(c.z));
  }
  return std::fclose(file) == 0;
}

std::vector<Vec3> read_golden(const std::string& path) {
  std::ifstream in(path);
  std::vector<Vec3> positions;
  double x, y, z;
  while (in >> x >> y >> z) positions.push_back({real(x), real(y), real(z)});  // test set-up only
  return positions;
}

std::string poses_golden_name(const std::string& positions_name) {
  const std::string suffix = "_positions.txt";
  return positions_name.substr(0, positions_name.size() - suffix.size()) + "_poses.txt";
}

bool write_golden_poses(const std::string& path, const SequenceRun& run) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return false;
  for (const FrameResult& frame : run.frames) {
    const Vec3& t = frame.camera_from_model.translation();
    const Mat33& r = frame.camera_from_model.rotation();
    std::fprintf(file, "%.17g %.17g %.17g", static_cast<double>(t.x), static_cast<double>(t.y), static_cast<double>(t.z));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) std::fprintf(file, " %.17g", static_cast<double>(r.m[i][j]));
    std::fprintf(file, "\n");
  }
  return std::fclose(file) == 0;
}

std::vector<GoldenPose> read_golden_poses(const std::string& path) {
  std::ifstream in(path);
  std::vector<GoldenPose> poses;
  GoldenPose pose;
  while (in >> pose.translation[0] >> pose.translation[1] >> pose.translation[2]) {
    for (double& r : pose.rotation) in >> r;
    if (!in) return {};
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace edgetrack_test
