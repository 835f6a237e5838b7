// SPDX-License-Identifier: BSD-3-Clause
/// The poses CSV's rows and lines.
#include "edgetrack/poses_csv.h"

#include <cstdint>
#include <cstdio>

namespace edgetrack {

void pose_columns(const Se3& camera_from_model, double t[3], double tu[3]) {
  const Vec3 translation = camera_from_model.translation(), theta_u = camera_from_model.theta_u();
  t[0] = static_cast<double>(translation.x);
  t[1] = static_cast<double>(translation.y);
  t[2] = static_cast<double>(translation.z);
  tu[0] = static_cast<double>(theta_u.x);
  tu[1] = static_cast<double>(theta_u.y);
  tu[2] = static_cast<double>(theta_u.z);
}

PosesCsvRow poses_csv_row(int frame, const FrameResult& result) {
  PosesCsvRow row;
  row.frame = frame;
  pose_columns(result.camera_from_model, row.t, row.tu);
  int64_t ns = 0;
  for (int64_t step : result.step_ns) ns += step;
  row.points = result.points_matched;
  row.ms = static_cast<double>(ns) / 1e6;
  row.status = result.status;
  row.edge_angle_deg = static_cast<double>(result.measures.gradient_angle_deg);
  return row;
}

std::string poses_csv_line(const PosesCsvRow& row) {
  char line[kPosesCsvLineBytes];
  poses_csv_line(row, line);
  return line;
}

void poses_csv_line(const PosesCsvRow& row, char (&line)[kPosesCsvLineBytes]) {
  std::snprintf(line, sizeof line, "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%.3f,%s,%.2f", row.frame, row.t[0], row.t[1],
                row.t[2], row.tu[0], row.tu[1], row.tu[2], row.points, row.ms, status_name(row.status),
                row.edge_angle_deg);
}

}  // namespace edgetrack
