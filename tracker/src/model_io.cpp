// SPDX-License-Identifier: BSD-3-Clause
/// The Wavefront .obj reader and the model loader (formats in docs/FORMATS.md); .cao is cao_reader.cpp.
#include "edgetrack/model_io.h"

#include "text_lines.h"

namespace edgetrack {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    char c = text[text.size() - suffix.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != suffix[i]) return false;
  }
  return true;
}

/// The records of an .obj's lines; `path` names it in errors.
Result<Polygons> read_obj_lines(const std::string& path, const std::vector<TextLine>& lines) {
  Polygons out;
  for (const TextLine& line : lines) {
    const std::string& kind = line.tokens[0];
    if (kind == "v") {
      Vec3 p;
      if (line.tokens.size() < 4 || !parse_real(line.tokens[1], p.x) || !parse_real(line.tokens[2], p.y) ||
          !parse_real(line.tokens[3], p.z))
        return Error{path, line.number, "expected a vertex: v x y z"};
      out.vertices.push_back(p);
    } else if (kind == "f") {
      if (line.tokens.size() < 4) return Error{path, line.number, "a face needs at least 3 vertices"};
      std::vector<int> face;
      for (size_t i = 1; i < line.tokens.size(); ++i) {
        const std::string token = line.tokens[i].substr(0, line.tokens[i].find('/'));
        long index = 0;
        if (!parse_int(token, index) || index == 0)
          return Error{path, line.number, "bad vertex reference '" + line.tokens[i] + "'"};
        const long count = static_cast<long>(out.vertices.size());
        const long zero_based = index > 0 ? index - 1 : count + index;
        if (zero_based < 0 || zero_based >= count)
          return Error{path, line.number, "vertex reference " + token + " is not among the " + std::to_string(count) +
                                              " vertices defined so far"};
        face.push_back(static_cast<int>(zero_based));
      }
      out.faces.push_back(face);
      out.face_attributes.emplace_back();
    } else if (kind == "l") {
      for (size_t i = 2; i < line.tokens.size(); ++i) {
        long a = 0, b = 0;
        const long count = static_cast<long>(out.vertices.size());
        if (!parse_int(line.tokens[i - 1].substr(0, line.tokens[i - 1].find('/')), a) ||
            !parse_int(line.tokens[i].substr(0, line.tokens[i].find('/')), b) || a < 1 || b < 1 || a > count ||
            b > count)
          return Error{path, line.number, "bad line record"};
        out.lines.emplace_back(static_cast<int>(a - 1), static_cast<int>(b - 1));
      }
    }
  }
  return out;
}

}  // namespace

Result<Polygons> read_obj(const std::string& path) {
  std::vector<TextLine> lines;
  auto read = read_text_lines(path, lines);
  if (!read.ok()) return read.error();
  return read_obj_lines(path, lines);
}

Result<Polygons> read_obj_text(const std::string& text, const std::string& name) {
  if (text.size() > kMaxTextFileBytes)
    return Error{name, 0, "the model's text is more than " + std::to_string(kMaxTextFileBytes) + " bytes"};
  std::vector<TextLine> lines;
  split_text_lines(text, lines);
  return read_obj_lines(name, lines);
}

Result<EdgeModel> load_model(const std::string& path, const EdgeRules& rules) {
  Result<Polygons> polygons = ends_with(path, ".cao")   ? read_cao(path)
                              : ends_with(path, ".obj") ? read_obj(path)
                                                        : Result<Polygons>(Error{path, 0, "unknown model format: use .cao or .obj"});
  if (!polygons.ok()) return polygons.error();
  return build_edge_model(polygons.value(), rules, path);
}

Result<EdgeModel> load_model_text(const std::string& text, const std::string& name,
                                  const std::optional<std::string>& base_directory, const EdgeRules& rules) {
  Result<Polygons> polygons = ends_with(name, ".cao")   ? read_cao_text(text, name, base_directory)
                              : ends_with(name, ".obj") ? read_obj_text(text, name)
                                                        : Result<Polygons>(Error{name, 0, "unknown model format: name the text .cao or .obj"});
  if (!polygons.ok()) return polygons.error();
  return build_edge_model(polygons.value(), rules, name);
}

}  // namespace edgetrack
