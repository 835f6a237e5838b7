// SPDX-License-Identifier: BSD-3-Clause
/// The poses of poses.txt (tx ty tz tux tuy tuz per line, '#' comments), shared by the
/// lod_visibility programs, which link different libraries.
#pragma once

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

inline std::vector<std::array<double, 6>> read_pose_lines(const char* path) {
  std::vector<std::array<double, 6>> poses;
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::array<double, 6> pose{};
    for (double& value : pose) in >> value;
    poses.push_back(pose);
  }
  return poses;
}
