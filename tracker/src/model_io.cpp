// SPDX-License-Identifier: BSD-3-Clause
/// Readers for ViSP .cao and Wavefront .obj models (formats in docs/FORMATS.md).
#include "edgetrack/model_io.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace edgetrack {
namespace {

/// One non-empty line of a file with its comment removed, and its 1-based number.
struct Line {
  int number = 0;
  std::vector<std::string> tokens;
};

bool read_lines(const std::string& path, std::vector<Line>& lines) {
  std::ifstream in(path);
  if (!in) return false;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    const size_t hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    std::istringstream words(text);
    Line line;
    line.number = number;
    std::string word;
    while (words >> word) line.tokens.push_back(word);
    if (!line.tokens.empty()) lines.push_back(line);
  }
  return true;
}

bool parse_int(const std::string& token, long& value) {
  char* end = nullptr;
  value = std::strtol(token.c_str(), &end, 10);
  return !token.empty() && *end == '\0';
}

bool parse_real(const std::string& token, real& value) {
  char* end = nullptr;
  const double parsed = std::strtod(token.c_str(), &end);
  if (token.empty() || *end != '\0') return false;
  value = real(parsed);  // set-up time conversion, never in the frame loop
  return true;
}

/// Walks the .cao records in order, keeping the position for error messages.
class CaoReader {
 public:
  CaoReader(std::string path, std::vector<Line> lines) : path_(std::move(path)), lines_(std::move(lines)) {}

  Result<Polygons> read() {
    Polygons out;
    int version = 1;
    if (pos_ < lines_.size() && (lines_[pos_].tokens[0] == "V1" || lines_[pos_].tokens[0] == "V2")) {
      version = lines_[pos_].tokens[0] == "V2" ? 2 : 1;
      ++pos_;
    }
    while (pos_ < lines_.size() && lines_[pos_].tokens[0].compare(0, 5, "load(") == 0)
      return error("load() includes of other .cao files are not supported; merge the parts into one file");

    long count = 0;
    if (!read_count("3D points", count)) return error_;
    for (long k = 0; k < count; ++k) {
      const Line* line = next("a 3D point");
      if (!line) return error_;
      const size_t needed = version == 2 ? 5 : 3;
      Vec3 p;
      if (line->tokens.size() < needed || !parse_real(line->tokens[0], p.x) || !parse_real(line->tokens[1], p.y) ||
          !parse_real(line->tokens[2], p.z))
        return error_at(*line, "expected a 3D point: X Y Z" + std::string(version == 2 ? " i j" : ""));
      out.vertices.push_back(p);
    }
    const long points = count;

    if (!read_count("3D lines", count)) return error_;
    std::vector<std::pair<int, int>> lines;
    for (long k = 0; k < count; ++k) {
      const Line* line = next("a 3D line");
      if (!line) return error_;
      long a = 0, b = 0;
      if (line->tokens.size() < 2 || !parse_int(line->tokens[0], a) || !parse_int(line->tokens[1], b))
        return error_at(*line, "expected a 3D line: two point indices");
      if (a < 0 || a >= points || b < 0 || b >= points)
        return error_at(*line, "line uses a point index outside 0.." + std::to_string(points - 1));
      lines.emplace_back(static_cast<int>(a), static_cast<int>(b));
    }

    if (!read_count("faces from lines", count)) return error_;
    std::vector<bool> line_in_face(lines.size(), false);
    for (long k = 0; k < count; ++k) {
      const Line* line = next("a face from lines");
      if (!line) return error_;
      std::vector<long> indices;
      if (!read_indexed_record(*line, indices)) return error_at(*line, "expected: n line_1 ... line_n");
      std::vector<std::pair<int, int>> segments;
      for (long index : indices) {
        if (index < 0 || index >= static_cast<long>(lines.size()))
          return error_at(*line, "face uses a line index outside 0.." + std::to_string(lines.size()) + "-1");
        segments.push_back(lines[index]);
        line_in_face[index] = true;
      }
      std::vector<int> loop;
      if (!chain(segments, loop)) return error_at(*line, "the face's lines do not form one closed loop");
      out.faces.push_back(loop);
      out.face_names.push_back(parameter(*line, "name"));
    }
    for (size_t i = 0; i < lines.size(); ++i)
      if (!line_in_face[i]) out.lines.push_back(lines[i]);

    if (!read_count("faces from points", count)) return error_;
    for (long k = 0; k < count; ++k) {
      const Line* line = next("a face from points");
      if (!line) return error_;
      std::vector<long> indices;
      if (!read_indexed_record(*line, indices)) return error_at(*line, "expected: n point_1 ... point_n");
      std::vector<int> face;
      for (long index : indices) {
        if (index < 0 || index >= points)
          return error_at(*line, "face uses a point index outside 0.." + std::to_string(points - 1));
        face.push_back(static_cast<int>(index));
      }
      out.faces.push_back(face);
      out.face_names.push_back(parameter(*line, "name"));
    }

    // Older files stop here; otherwise the cylinder and circle counts follow.
    if (pos_ < lines_.size()) {
      if (!read_count("3D cylinders", count)) return error_;
      if (count > 0) return error_at(lines_[pos_ - 1], "cylinders are not supported: edgetrack tracks straight edges only");
    }
    if (pos_ < lines_.size()) {
      if (!read_count("3D circles", count)) return error_;
      if (count > 0) return error_at(lines_[pos_ - 1], "circles are not supported: edgetrack tracks straight edges only");
    }
    if (pos_ < lines_.size()) return error_at(lines_[pos_], "unexpected content after the circles section");
    return out;
  }

 private:
  Error error() const { return error_; }
  Error error(const std::string& message) const {
    return Error{path_, pos_ < lines_.size() ? lines_[pos_].number : 0, message};
  }
  Error error_at(const Line& line, const std::string& message) const { return Error{path_, line.number, message}; }

  const Line* next(const std::string& what) {
    if (pos_ >= lines_.size()) {
      error_ = Error{path_, lines_.empty() ? 0 : lines_.back().number, "file ends where " + what + " was expected"};
      return nullptr;
    }
    return &lines_[pos_++];
  }

  bool read_count(const std::string& section, long& count) {
    const Line* line = next("the number of " + section);
    if (!line) return false;
    if (!parse_int(line->tokens[0], count) || count < 0 || count > 100000) {
      error_ = error_at(*line, "expected the number of " + section + ", found '" + line->tokens[0] + "'");
      return false;
    }
    return true;
  }

  /// "n i_1 ... i_n [name=value ...]"
  static bool read_indexed_record(const Line& line, std::vector<long>& indices) {
    long n = 0;
    if (!parse_int(line.tokens[0], n) || n < 2 || static_cast<size_t>(n) + 1 > line.tokens.size()) return false;
    for (long i = 1; i <= n; ++i) {
      long index = 0;
      if (!parse_int(line.tokens[i], index)) return false;
      indices.push_back(index);
    }
    return true;
  }

  static std::string parameter(const Line& line, const std::string& key) {
    for (const std::string& token : line.tokens)
      if (token.compare(0, key.size() + 1, key + "=") == 0) return token.substr(key.size() + 1);
    return {};
  }

  /// Orders segments given in any orientation into one closed loop of vertices.
  static bool chain(std::vector<std::pair<int, int>> segments, std::vector<int>& loop) {
    if (segments.size() < 3) return false;
    loop.push_back(segments[0].first);
    int tail = segments[0].second;
    segments.erase(segments.begin());
    while (!segments.empty()) {
      bool found = false;
      for (size_t i = 0; i < segments.size() && !found; ++i) {
        if (segments[i].first == tail || segments[i].second == tail) {
          loop.push_back(tail);
          tail = segments[i].first == tail ? segments[i].second : segments[i].first;
          segments.erase(segments.begin() + static_cast<std::ptrdiff_t>(i));
          found = true;
        }
      }
      if (!found) return false;
    }
    return tail == loop[0];
  }

  std::string path_;
  std::vector<Line> lines_;
  size_t pos_ = 0;
  Error error_;
};

bool ends_with(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    char c = text[text.size() - suffix.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != suffix[i]) return false;
  }
  return true;
}

}  // namespace

Result<Polygons> read_cao(const std::string& path) {
  std::vector<Line> lines;
  if (!read_lines(path, lines)) return Error{path, 0, "cannot open the file"};
  return CaoReader(path, std::move(lines)).read();
}

Result<Polygons> read_obj(const std::string& path) {
  std::vector<Line> lines;
  if (!read_lines(path, lines)) return Error{path, 0, "cannot open the file"};
  Polygons out;
  for (const Line& line : lines) {
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
      out.face_names.emplace_back();
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

Result<EdgeModel> load_model(const std::string& path, const EdgeRules& rules) {
  Result<Polygons> polygons = ends_with(path, ".cao")   ? read_cao(path)
                              : ends_with(path, ".obj") ? read_obj(path)
                                                        : Result<Polygons>(Error{path, 0, "unknown model format: use .cao or .obj"});
  if (!polygons.ok()) return polygons.error();
  return build_edge_model(polygons.value(), rules, path);
}

}  // namespace edgetrack
