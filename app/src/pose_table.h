// SPDX-License-Identifier: BSD-3-Clause
/// The CSV files of the application: the tracked poses (`frame,tx,ty,tz,tux,tuy,tuz,points,ms,status,edge_angle_deg`)
/// and the ground truth of a synthetic sequence (`frame,tx,ty,tz,tux,tuy,tuz`). Poses are
/// camera_from_model (ViSP's cMo): translation in metres, thetaU in radians.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "edgetrack/poses_csv.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack_app {

constexpr const char* kPosesHeader = edgetrack::kPosesCsvHeader;
/// The poses header of files written before the edge angle column; read as kPosesHeader's.
constexpr const char* kPosesHeaderWithoutAngle = "frame,tx,ty,tz,tux,tuy,tuz,points,ms,status";
constexpr const char* kTruthHeader = "frame,tx,ty,tz,tux,tuy,tuz";

struct PoseRow {
  int frame = 0;
  double t[3] = {0, 0, 0};   ///< metres
  double tu[3] = {0, 0, 0};  ///< radians
  int points = 0;            ///< poses file only
  double ms = 0;
  bool lost = false;       ///< status `lost`
  bool uncertain = false;  ///< status `uncertain`; neither: `tracked` (older files: `ok`)
  /// The frame's quality figure (FrameMeasures::gradient_angle_deg), degrees, 0 to 90; 0 in
  /// files written before the column.
  double edge_angle_deg = 0;
};

/// Reads a poses or truth file; `header` is the header it must start with (extra columns after
/// it are not allowed; kPosesHeader also reads kPosesHeaderWithoutAngle's files). Frames are whole numbers listed once each in increasing order, and every
/// value is finite. Errors name the file and the line.
edgetrack::Result<std::vector<PoseRow>> read_pose_table(const std::string& path, const std::string& header);

/// The ground truth of a sequence: a truth CSV (kTruthHeader), or a directory of one ViSP pose
/// file per frame (read_pos: a .pos vector or a 4x4 homogeneous matrix), each numbered by the
/// number its name ends with (Castle-simu's CameraPose/Camera_001.txt is frame 1). In a
/// directory every regular file is a pose file; a name without a number, or two with one
/// number, is an error naming the file.
edgetrack::Result<std::vector<PoseRow>> read_truth(const std::string& path);

/// Writes rows as they come, into `<path>.partial`; close() renames it to `path`, so a run that
/// fails or is killed never leaves a partial file under the name of a complete one. Poses files
/// carry the tracking columns, truth files do not.
class PoseTableWriter {
 public:
  static edgetrack::Result<PoseTableWriter> open(const std::string& path, bool with_tracking);
  PoseTableWriter(PoseTableWriter&& other) noexcept;
  PoseTableWriter& operator=(PoseTableWriter&&) = delete;
  ~PoseTableWriter();
  void write(const PoseRow& row);
  /// A poses file's row as the library makes it (edgetrack::poses_csv_row).
  void write(const edgetrack::PosesCsvRow& row);
  /// Flushes and closes; an Error when anything failed to reach the file.
  edgetrack::Result<bool> close();

 private:
  PoseTableWriter(std::FILE* file, std::string path, bool with_tracking)
      : file_(file), path_(std::move(path)), with_tracking_(with_tracking) {}
  std::FILE* file_;
  std::string path_;
  bool with_tracking_;
  bool failed_ = false;
};

PoseRow pose_row(int frame, const edgetrack::Se3& camera_from_model);
edgetrack::Se3 pose_of(const PoseRow& row);

}  // namespace edgetrack_app
