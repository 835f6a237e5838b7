// SPDX-License-Identifier: BSD-3-Clause
/// Reading and writing ViSP .pos pose vectors.
#include "edgetrack/pose_io.h"

#include <cstdio>

#include "edgetrack/number_text.h"

namespace edgetrack {

Result<Se3> read_pos(const std::string& path) {
  auto words = read_words(path);
  if (!words.ok()) return words.error();
  const std::vector<Word>& w = words.value();
  if (w.size() < 6)
    return Error{path, w.empty() ? 0 : w.back().line,
                 "expected 6 numbers (tx ty tz tux tuy tuz), found " + std::to_string(w.size())};
  if (w.size() > 6) return Error{path, w[6].line, "more than 6 values: '" + w[6].text + "'"};
  static const FieldRange kFields[6] = {{"tx (m)", -kMaxPosTranslation, kMaxPosTranslation},
                                        {"ty (m)", -kMaxPosTranslation, kMaxPosTranslation},
                                        {"tz (m)", -kMaxPosTranslation, kMaxPosTranslation},
                                        {"tux (rad)", -kMaxPosRotation, kMaxPosRotation},
                                        {"tuy (rad)", -kMaxPosRotation, kMaxPosRotation},
                                        {"tuz (rad)", -kMaxPosRotation, kMaxPosRotation}};
  double values[6];
  for (int i = 0; i < 6; ++i) {
    auto value = parse_field(w[i].text, kFields[i], path, w[i].line);
    if (!value.ok()) return value.error();
    values[i] = value.value();
  }
  // Set-up time conversions from the file's decimal text.
  return Se3::from_theta_u({real(values[0]), real(values[1]), real(values[2])},
                           {real(values[3]), real(values[4]), real(values[5])});
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
