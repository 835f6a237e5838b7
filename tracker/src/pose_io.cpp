// SPDX-License-Identifier: BSD-3-Clause
/// Reading ViSP's pose files (pose vectors and homogeneous matrices) and writing .pos files.
#include "edgetrack/pose_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "edgetrack/number_text.h"

namespace edgetrack {

namespace {

constexpr FieldRange kTranslation[3] = {{"tx (m)", -kMaxPosTranslation, kMaxPosTranslation},
                                        {"ty (m)", -kMaxPosTranslation, kMaxPosTranslation},
                                        {"tz (m)", -kMaxPosTranslation, kMaxPosTranslation}};

/// The pose vector tx ty tz tux tuy tuz.
Result<Se3> pose_from_vector(const std::vector<Word>& w, const std::string& path) {
  static const FieldRange kRotation[3] = {{"tux (rad)", -kMaxPosRotation, kMaxPosRotation},
                                          {"tuy (rad)", -kMaxPosRotation, kMaxPosRotation},
                                          {"tuz (rad)", -kMaxPosRotation, kMaxPosRotation}};
  double values[6];
  for (int i = 0; i < 6; ++i) {
    auto value = parse_field(w[i].text, i < 3 ? kTranslation[i] : kRotation[i - 3], path, w[i].line);
    if (!value.ok()) return value.error();
    values[i] = value.value();
  }
  // Set-up time conversions from the file's decimal text.
  return Se3::from_theta_u({real(values[0]), real(values[1]), real(values[2])},
                           {real(values[3]), real(values[4]), real(values[5])});
}

/// The homogeneous matrix [R t; 0 0 0 1], row by row: R a rotation to within
/// kPoseMatrixTolerance, the last row 0 0 0 1 to within the same.
Result<Se3> pose_from_matrix(const std::vector<Word>& w, const std::string& path) {
  static const FieldRange kEntry = {"a rotation entry", -1 - kPoseMatrixTolerance, 1 + kPoseMatrixTolerance};
  static const FieldRange kLastRow = {"a last-row entry", -kMaxPosTranslation, kMaxPosTranslation};
  double m[4][4];
  for (int i = 0; i < 16; ++i) {
    const int row = i / 4, column = i % 4;
    const FieldRange& range = row == 3 ? kLastRow : column == 3 ? kTranslation[row] : kEntry;
    auto value = parse_field(w[i].text, range, path, w[i].line);
    if (!value.ok()) return value.error();
    m[row][column] = value.value();
  }
  for (int column = 0; column < 4; ++column)
    if (std::fabs(m[3][column] - (column == 3 ? 1 : 0)) > kPoseMatrixTolerance)
      return Error{path, w[12].line, "the last row of a homogeneous matrix must be 0 0 0 1"};
  double worst = 0;  // the largest entry of R R^T - I
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double dot = m[a][0] * m[b][0] + m[a][1] * m[b][1] + m[a][2] * m[b][2];
      worst = std::max(worst, std::fabs(dot - (a == b ? 1 : 0)));
    }
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (worst > kPoseMatrixTolerance || det < 0) {
    char text[160];
    std::snprintf(text, sizeof text, "the upper-left 3x3 is not a rotation (R R^T is %.2g off the identity, det %.6g)",
                  worst, det);
    return Error{path, w[0].line, text};
  }
  Mat33 rotation;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) rotation.m[a][b] = real(m[a][b]);
  // Through thetaU, as a .pos file goes: the pose's rotation is exp() of it, orthonormal to
  // real's resolution whatever the file's precision.
  return Se3::from_theta_u({real(m[0][3]), real(m[1][3]), real(m[2][3])}, rotation_log(rotation));
}

}  // namespace

Result<Se3> read_pos(const std::string& path) {
  auto words = read_words(path);
  if (!words.ok()) return words.error();
  const std::vector<Word>& w = words.value();
  if (w.size() == 6) return pose_from_vector(w, path);
  if (w.size() == 16) return pose_from_matrix(w, path);
  const std::string expected = "expected 6 numbers (a ViSP .pos: tx ty tz tux tuy tuz) or 16 (a 4x4 homogeneous "
                               "matrix, as vpHomogeneousMatrix::save writes it)";
  if (w.size() > 16) return Error{path, w[16].line, expected + ", found more than 16: '" + w[16].text + "'"};
  return Error{path, w.empty() ? 0 : w.back().line, expected + ", found " + std::to_string(w.size())};
}

Result<bool> write_pos(const std::string& path, const Se3& camera_from_model) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  const Vec3 t = camera_from_model.translation();
  const Vec3 tu = camera_from_model.theta_u();
  const real values[6] = {t.x, t.y, t.z, tu.x, tu.y, tu.z};
  bool ok = true;
  for (const real& value : values) ok = ok && std::fprintf(file, "%.10g\n", static_cast<double>(value)) > 0;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

}  // namespace edgetrack
