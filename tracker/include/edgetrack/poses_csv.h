// SPDX-License-Identifier: BSD-3-Clause
/// The poses CSV (docs/FORMATS.md): what `edgetrack track --poses` writes, `edgetrack eval` reads
/// and a program on the API prints, one line per tracked frame under kPosesCsvHeader.
#pragma once

#include <string>

#include "edgetrack/se3.h"
#include "edgetrack/tracker.h"
#include "edgetrack/tracking_status.h"

namespace edgetrack {

constexpr const char* kPosesCsvHeader = "frame,tx,ty,tz,tux,tuy,tuz,points,ms,status,edge_angle_deg";

/// One frame's line of the poses CSV, as plain numbers.
struct PosesCsvRow {
  int frame = 0;
  double t[3] = {0, 0, 0};   ///< camera_from_model's translation, metres
  double tu[3] = {0, 0, 0};  ///< its rotation as theta-u, radians
  int points = 0;            ///< FrameResult::points_matched
  double ms = 0;             ///< the frame's step times together, milliseconds
  TrackingStatus status = TrackingStatus::kTracked;
  double edge_angle_deg = 0;  ///< FrameMeasures::gradient_angle_deg, the per-frame quality figure
};

/// The pose columns: camera_from_model's translation (metres) and theta-u (radians) as doubles.
void pose_columns(const Se3& camera_from_model, double t[3], double tu[3]);

/// The row of frame number `frame`, which Tracker::track answered with `result`.
PosesCsvRow poses_csv_row(int frame, const FrameResult& result);

/// The row as a line of the file, without its newline: poses to 9 significant digits, ms to
/// the microsecond, the status as status_name spells it, the edge angle to 0.01 degree.
std::string poses_csv_line(const PosesCsvRow& row);
/// The same line into `line` (a firmware's, which allocates nothing); kPosesCsvLineBytes holds any row.
constexpr size_t kPosesCsvLineBytes = 256;
void poses_csv_line(const PosesCsvRow& row, char (&line)[kPosesCsvLineBytes]);

}  // namespace edgetrack
