// SPDX-License-Identifier: BSD-3-Clause
/// Reading and writing the poses and ground-truth CSV files.
#include "pose_table.h"

#include "edgetrack/input_file.h"
#include "edgetrack/number_text.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/tracking_status.h"
#include "frame_source.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

using edgetrack::Error;
using edgetrack::Result;
using edgetrack::Se3;

namespace edgetrack_app {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::stringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

/// The range of each numeric column: a pose as a .pos file bounds it, milliseconds and frame
/// and point counts up to 10^9, the edge angle 0 to 90 degrees (column 10 is the status).
const edgetrack::FieldRange kColumns[11] = {
    {"frame", 0, 1e9},
    {"column 2", -edgetrack::kMaxPosTranslation, edgetrack::kMaxPosTranslation},
    {"column 3", -edgetrack::kMaxPosTranslation, edgetrack::kMaxPosTranslation},
    {"column 4", -edgetrack::kMaxPosTranslation, edgetrack::kMaxPosTranslation},
    {"column 5", -edgetrack::kMaxPosRotation, edgetrack::kMaxPosRotation},
    {"column 6", -edgetrack::kMaxPosRotation, edgetrack::kMaxPosRotation},
    {"column 7", -edgetrack::kMaxPosRotation, edgetrack::kMaxPosRotation},
    {"points", 0, 1e9},
    {"column 9", 0, 1e9},
    {"status", 0, 0},
    {"edge_angle_deg", 0, 90}};

std::string partial_path(const std::string& path) { return path + ".partial"; }

/// The status a row carries as its two flags.
edgetrack::TrackingStatus status_of(const PoseRow& row) {
  return row.lost ? edgetrack::TrackingStatus::kLost
                  : row.uncertain ? edgetrack::TrackingStatus::kUncertain : edgetrack::TrackingStatus::kTracked;
}

}  // namespace

Result<std::vector<PoseRow>> read_pose_table(const std::string& path, const std::string& header) {
  auto text = edgetrack::read_input_text(path);
  if (!text.ok()) return text.error();
  std::istringstream in(text.value());
  std::string line;
  if (!std::getline(in, line)) return Error{path, 1, "empty file (expected the header '" + header + "')"};
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const bool without_angle = header == std::string(kPosesHeader) && line == kPosesHeaderWithoutAngle;
  if (line != header && !without_angle)
    return Error{path, 1, "header is '" + line + "', expected '" + header + "'"};
  const size_t columns = split(line).size();
  const bool tracking = columns >= 10;
  std::vector<PoseRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != columns)
      return Error{path, number, std::to_string(cells.size()) + " columns, expected " + std::to_string(columns)};
    PoseRow row;
    auto frame = edgetrack::parse_whole_field(cells[0], kColumns[0], path, number);
    if (!frame.ok()) return frame.error();
    row.frame = static_cast<int>(frame.value());
    if (!rows.empty() && row.frame <= rows.back().frame)
      return Error{path, number, "frame " + cells[0] + (row.frame == rows.back().frame ? " appears twice" : " comes after frame " + std::to_string(rows.back().frame)) + ": frames must be listed once each, in increasing order"};
    double values[9];
    const size_t numeric = tracking ? 9 : 7;
    for (size_t i = 1; i < numeric; ++i) {
      if (i == 7) continue;  // points: a whole number, below
      auto value = edgetrack::parse_field(cells[i], kColumns[i], path, number);
      if (!value.ok()) return value.error();
      values[i] = value.value();
    }
    for (int i = 0; i < 3; ++i) {
      row.t[i] = values[1 + i];
      row.tu[i] = values[4 + i];
    }
    if (tracking) {
      auto points = edgetrack::parse_whole_field(cells[7], kColumns[7], path, number);
      if (!points.ok()) return points.error();
      row.points = static_cast<int>(points.value());
      row.ms = values[8];
      // `ok` is how files written before the status took the library's names say `tracked`.
      if (cells[9] != "tracked" && cells[9] != "ok" && cells[9] != "uncertain" && cells[9] != "lost")
        return Error{path, number, "status is '" + cells[9] + "', expected tracked, uncertain or lost"};
      row.lost = cells[9] == "lost";
      row.uncertain = cells[9] == "uncertain";
      if (columns == 11) {
        auto angle = edgetrack::parse_field(cells[10], kColumns[10], path, number);
        if (!angle.ok()) return angle.error();
        row.edge_angle_deg = angle.value();
      }
    }
    rows.push_back(row);
  }
  if (rows.empty()) return Error{path, 0, "no rows after the header"};
  return rows;
}

namespace {

/// The regular files of `dir` in name order, or an Error naming it.
Result<std::vector<std::string>> regular_files(const std::string& dir) {
  std::error_code error;
  std::vector<std::string> paths;
  std::filesystem::directory_iterator it(dir, error), end;
  for (; !error && it != end; it.increment(error)) {
    std::error_code type_error;
    if (it->is_regular_file(type_error) && !type_error) paths.push_back(it->path().string());
  }
  if (error) return Error{dir, 0, "cannot list the directory: " + error.message()};
  std::sort(paths.begin(), paths.end());
  return paths;
}

Result<std::vector<PoseRow>> read_pose_directory(const std::string& dir) {
  auto paths = regular_files(dir);
  if (!paths.ok()) return paths.error();
  std::map<int, PoseRow> by_frame;
  for (const std::string& path : paths.value()) {
    const int frame = number_in_name(path);
    if (frame < 0) return Error{path, 0, "a pose file of a truth directory must end its name with the frame number"};
    auto pose = edgetrack::read_pos(path);
    if (!pose.ok()) return pose.error();
    if (!by_frame.emplace(frame, pose_row(frame, pose.value())).second)
      return Error{path, 0, "a second pose file for frame " + std::to_string(frame)};
  }
  if (by_frame.empty()) return Error{dir, 0, "no pose files in the directory"};
  std::vector<PoseRow> rows;
  for (const auto& entry : by_frame) rows.push_back(entry.second);
  return rows;
}

}  // namespace

Result<std::vector<PoseRow>> read_truth(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return read_pose_directory(path);
  return read_pose_table(path, kTruthHeader);
}

Result<PoseTableWriter> PoseTableWriter::open(const std::string& path, bool with_tracking) {
  std::FILE* file = std::fopen(partial_path(path).c_str(), "w");
  if (!file) return Error{path, 0, "cannot open the file for writing (as " + partial_path(path) + ")"};
  PoseTableWriter writer(file, path, with_tracking);
  if (std::fprintf(file, "%s\n", with_tracking ? kPosesHeader : kTruthHeader) < 0) writer.failed_ = true;
  return writer;
}

PoseTableWriter::PoseTableWriter(PoseTableWriter&& other) noexcept
    : file_(other.file_), path_(std::move(other.path_)), with_tracking_(other.with_tracking_), failed_(other.failed_) {
  other.file_ = nullptr;
}

PoseTableWriter::~PoseTableWriter() {
  if (file_) std::fclose(file_);
}

void PoseTableWriter::write(const PoseRow& row) {
  if (!file_) return;
  if (with_tracking_) {
    edgetrack::PosesCsvRow csv;
    csv.frame = row.frame;
    std::copy(row.t, row.t + 3, csv.t);
    std::copy(row.tu, row.tu + 3, csv.tu);
    csv.points = row.points;
    csv.ms = row.ms;
    csv.status = status_of(row);
    csv.edge_angle_deg = row.edge_angle_deg;
    return write(csv);
  }
  if (std::fprintf(file_, "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", row.frame, row.t[0], row.t[1], row.t[2], row.tu[0],
                   row.tu[1], row.tu[2]) < 0)
    failed_ = true;
}

void PoseTableWriter::write(const edgetrack::PosesCsvRow& row) {
  if (!file_) return;
  if (std::fprintf(file_, "%s\n", edgetrack::poses_csv_line(row).c_str()) < 0) failed_ = true;
}

Result<bool> PoseTableWriter::close() {
  if (!file_) return Error{path_, 0, "already closed"};
  const bool ok = std::fclose(file_) == 0 && !failed_;
  file_ = nullptr;
  if (!ok) return Error{path_, 0, "write failed (the rows written so far stay in " + partial_path(path_) + ")"};
  if (std::rename(partial_path(path_).c_str(), path_.c_str()) != 0)
    return Error{path_, 0, "cannot rename " + partial_path(path_) + " to it"};
  return true;
}

PoseRow pose_row(int frame, const Se3& camera_from_model) {
  PoseRow row;
  row.frame = frame;
  edgetrack::pose_columns(camera_from_model, row.t, row.tu);
  return row;
}

Se3 pose_of(const PoseRow& row) {
  return Se3::from_theta_u({real(row.t[0]), real(row.t[1]), real(row.t[2])},
                           {real(row.tu[0]), real(row.tu[1]), real(row.tu[2])});
}

}  // namespace edgetrack_app
