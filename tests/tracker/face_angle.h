// SPDX-License-Identifier: BSD-3-Clause
/// The tests' own measure of ViSP's face angle, in double, independent of the tracker's.
#pragma once

#include <cmath>

#include "edgetrack/edge_model.h"
#include "edgetrack/se3.h"

namespace edgetrack_test {

/// The angle between face f's normal and the direction from its centre to the camera (degrees).
inline double face_angle_degrees(const edgetrack::EdgeModel& model, int f, const edgetrack::Se3& pose) {
  double c[3] = {0, 0, 0};
  for (int v : model.faces[f].vertices) {
    const edgetrack::Vec3 p = pose * model.vertices[v];
    c[0] += static_cast<double>(p.x);
    c[1] += static_cast<double>(p.y);
    c[2] += static_cast<double>(p.z);
  }
  const edgetrack::Vec3 n = pose.rotation() * model.faces[f].normal;
  const double length = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double d = -(c[0] * static_cast<double>(n.x) + c[1] * static_cast<double>(n.y) + c[2] * static_cast<double>(n.z));
  return std::acos(d / length) * 180 / 3.14159265358979323846;
}

}  // namespace edgetrack_test
