// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's .cao format as vpMbTracker::loadCAOModel reads it (docs/FORMATS.md): load() includes,
/// points, lines, faces, cylinders, circles and their key=value parameters.
#include <cmath>
#include <optional>
#include <unordered_set>
#include <utility>

#include "edgetrack/model_io.h"
#include "edgetrack/se3.h"
#include "text_lines.h"

namespace edgetrack {
namespace {

std::string parent_directory(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

/// "[a;b;c]" after a load() parameter's prefix; `angles` accepts a "deg" or "rad" suffix per value.
bool parse_triple(std::string text, bool angles, Vec3& out) {
  if (text.empty() || text.back() != ']') return false;
  text.pop_back();
  real values[3];
  size_t start = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t end = text.find(';', start);
    if ((k < 2) == (end == std::string::npos)) return false;
    std::string value = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    while (!value.empty() && value.front() == ' ') value.erase(0, 1);
    while (!value.empty() && value.back() == ' ') value.pop_back();
    bool degrees = false;
    if (angles && value.size() > 3 && (value.compare(value.size() - 3, 3, "deg") == 0 ||
                                       value.compare(value.size() - 3, 3, "rad") == 0)) {
      degrees = value.compare(value.size() - 3, 3, "deg") == 0;
      value.erase(value.size() - 3);
    }
    if (!parse_real(value, values[k])) return false;
    if (degrees) values[k] = values[k] * real(3.14159265358979323846 / 180);
    start = end + 1;
  }
  out = {values[0], values[1], values[2]};
  return true;
}

/// A load("path", t=[x;y;z], tu=[a;b;c]) line: the path and the included part's placement.
bool parse_load(const std::string& text, std::string& path, Se3& placement) {
  const size_t open = text.find('('), close = text.find(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return false;
  std::vector<std::string> params;
  std::string inside = text.substr(open + 1, close - open - 1);
  for (size_t start = 0;;) {
    const size_t comma = inside.find(',', start);
    std::string param = inside.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    while (!param.empty() && (param.front() == ' ' || param.front() == '\t')) param.erase(0, 1);
    while (!param.empty() && (param.back() == ' ' || param.back() == '\t')) param.pop_back();
    params.push_back(param);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (params[0].size() < 3 || params[0].front() != '"' || params[0].back() != '"') return false;
  path = params[0].substr(1, params[0].size() - 2);
  for (char& c : path)
    if (c == '\\') c = '/';
  Vec3 t, tu;
  for (size_t i = 1; i < params.size(); ++i) {
    const std::string& p = params[i];
    if (p.compare(0, 3, "t=[") == 0) {
      if (!parse_triple(p.substr(3), false, t)) return false;
    } else if (p.compare(0, 4, "tu=[") == 0) {
      if (!parse_triple(p.substr(4), true, tu)) return false;
    } else {
      return false;
    }
  }
  placement = Se3::from_theta_u(t, tu);
  return true;
}

/// The key=value parameters after a record's numbers, read as ViSP does: from the first token
/// after the numbers up to the first token that is not a known parameter; "quoted" names may
/// hold spaces.
bool parse_attributes(const TextLine& line, size_t first, PrimitiveAttributes& out, std::string& problem) {
  for (size_t i = first; i < line.tokens.size(); ++i) {
    const std::string& token = line.tokens[i];
    const size_t eq = token.find('=');
    if (eq == std::string::npos) return true;
    const std::string key = token.substr(0, eq);
    std::string value = token.substr(eq + 1);
    if (key == "name") {
      if (value.size() > 1 && value.front() == '"') {
        value.erase(0, 1);
        while (value.find('"') == std::string::npos && i + 1 < line.tokens.size()) value += " " + line.tokens[++i];
        value = value.substr(0, value.find('"'));
      }
      out.name = value;
    } else if (key == "useLod") {
      std::string lower = value;  // ViSP lowercases the value: True and TRUE are true
      for (char& c : lower)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
      if (lower != "true" && lower != "false" && lower != "1" && lower != "0") {
        problem = "useLod= takes true, false, 1 or 0, not '" + value + "'";
        return false;
      }
      out.use_lod = lower == "true" || lower == "1";
    } else if (key == "minLineLengthThreshold" || key == "minPolygonAreaThreshold") {
      real number(0);
      if (!parse_real(value, number)) {
        problem = key + "= takes a number, not '" + value + "'";
        return false;
      }
      (key == "minLineLengthThreshold" ? out.min_line_length : out.min_polygon_area) = number;
    } else {
      return true;  // ViSP stops at the first word that is not one of its parameters
    }
  }
  return true;
}

/// Orders segments given in any orientation into one closed loop of vertices.
bool chain_loop(std::vector<std::pair<int, int>> segments, std::vector<int>& loop) {
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

/// Appends `part` to `into`, moving its point indices past the points `into` already has.
void append_part(const Polygons& part, Polygons& into) {
  const int offset = static_cast<int>(into.vertices.size());
  into.vertices.insert(into.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (std::vector<int> face : part.faces) {
    for (int& v : face) v += offset;
    into.faces.push_back(face);
  }
  into.face_attributes.insert(into.face_attributes.end(), part.face_attributes.begin(), part.face_attributes.end());
  for (const auto& line : part.lines) into.lines.emplace_back(line.first + offset, line.second + offset);
  into.line_attributes.insert(into.line_attributes.end(), part.line_attributes.begin(), part.line_attributes.end());
  for (CylinderRecord c : part.cylinders) {
    c.axis_a += offset;
    c.axis_b += offset;
    into.cylinders.push_back(c);
  }
  for (CircleRecord c : part.circles) {
    c.centre += offset;
    c.plane_a += offset;
    c.plane_b += offset;
    into.circles.push_back(c);
  }
}

/// Reads one .cao file's records in order, keeping the position for error messages. Point
/// indices are local to the file; its load() lines come first and are handed out one by one
/// (next_include), then the parts they brought are merged before the file's own records.
class CaoFileReader {
 public:
  /// `include_directory`: where relative load() paths resolve (none for a model given as text
  /// without a base directory: a relative load() is then refused).
  CaoFileReader(std::string path, std::optional<std::string> include_directory, std::vector<TextLine> lines,
                const Se3& model_from_file);

  enum class Next { include, done, error };
  /// The next load() line's file (relative to this one) and where its points go in the model.
  Next next_include(std::string& path, Se3& model_from_part);
  /// The records after the load() lines, after the `parts` those brought.
  Result<Polygons> read_records(Polygons parts, bool included);

  const std::string& path() const { return path_; }
  int load_line() const { return load_line_; }  ///< the line of the last load() handed out
  const Error& error() const { return error_; }

 private:
  bool read_points(int version, Polygons& out);
  bool read_lines(std::vector<std::pair<int, int>>& lines, std::vector<PrimitiveAttributes>& attributes);
  bool read_faces_from_lines(const std::vector<std::pair<int, int>>& lines, std::vector<bool>& used, Polygons& out);
  bool read_faces_from_points(Polygons& out);
  bool read_cylinders(Polygons& out);
  bool read_circles(Polygons& out);

  bool fail(const TextLine& line, const std::string& message) {
    error_ = Error{path_, line.number, message};
    return false;
  }
  const TextLine* next(const std::string& what) {
    if (pos_ >= lines_.size()) {
      error_ = Error{path_, lines_.empty() ? 0 : lines_.back().number, "file ends where " + what + " was expected"};
      return nullptr;
    }
    return &lines_[pos_++];
  }
  bool read_count(const std::string& section, long& count) {
    const TextLine* line = next("the number of " + section);
    if (!line) return false;
    if (!parse_int(line->tokens[0], count) || count < 0 || count > 100000)
      return fail(*line, "expected the number of " + section + ", found '" + line->tokens[0] + "'");
    return true;
  }
  /// A count line, then that many records, each read by read_record(line).
  template <class ReadRecord>
  bool read_section(const std::string& section, const std::string& record, ReadRecord read_record) {
    long count = 0;
    if (!read_count(section, count)) return false;
    for (long k = 0; k < count; ++k) {
      const TextLine* line = next(record);
      if (!line || !read_record(*line)) return false;
    }
    return true;
  }
  /// "n i_1 ... i_n [parameters]", each index in [0, limit).
  bool read_indexed(const TextLine& line, long limit, const std::string& what, std::vector<long>& indices,
                    PrimitiveAttributes& attributes) {
    long n = 0;
    if (!parse_int(line.tokens[0], n) || n < 2 || static_cast<size_t>(n) + 1 > line.tokens.size())
      return fail(line, "expected: n " + what + "_1 ... " + what + "_n");
    for (long i = 1; i <= n; ++i) {
      long index = 0;
      if (!parse_int(line.tokens[i], index)) return fail(line, "expected a " + what + " index, found '" + line.tokens[i] + "'");
      if (index < 0 || index >= limit)
        return fail(line, "a " + what + " index " + std::to_string(index) + " outside 0.." + std::to_string(limit - 1));
      indices.push_back(index);
    }
    return attributes_of(line, static_cast<size_t>(n) + 1, attributes);
  }
  bool attributes_of(const TextLine& line, size_t first, PrimitiveAttributes& attributes) {
    std::string problem;
    return parse_attributes(line, first, attributes, problem) || fail(line, problem);
  }
  bool point_index(const TextLine& line, size_t token, long& index) {
    if (token >= line.tokens.size() || !parse_int(line.tokens[token], index)) return false;
    return index >= 0 && index < points_;
  }

  std::string path_;
  std::optional<std::string> include_directory_;
  std::vector<TextLine> lines_;
  Se3 model_from_file_;
  size_t pos_ = 0;
  int version_ = 1;
  int load_line_ = 0;
  long points_ = 0;
  Error error_;
};

CaoFileReader::CaoFileReader(std::string path, std::optional<std::string> include_directory,
                             std::vector<TextLine> lines, const Se3& model_from_file)
    : path_(std::move(path)),
      include_directory_(std::move(include_directory)),
      lines_(std::move(lines)),
      model_from_file_(model_from_file) {
  const std::string& head = lines_.empty() ? std::string() : lines_[0].tokens[0];
  if (head.size() == 2 && head[0] == 'V' && head[1] >= '0' && head[1] <= '9') {
    version_ = head[1] - '0';
    ++pos_;
  }
}

CaoFileReader::Next CaoFileReader::next_include(std::string& path, Se3& model_from_part) {
  if (pos_ >= lines_.size() || (lines_[pos_].tokens[0][0] != 'l' && lines_[pos_].tokens[0][0] != 'L'))
    return Next::done;
  const TextLine& line = lines_[pos_++];
  std::string relative;
  Se3 placement;
  if (line.tokens[0].compare(0, 4, "load") != 0 || !parse_load(line.text, relative, placement)) {
    fail(line, "expected load(\"file.cao\") with optional t=[x;y;z] and tu=[a;b;c]");
    return Next::error;
  }
  load_line_ = line.number;
  if (relative[0] != '/' && !include_directory_) {
    fail(line, "load(\"" + relative + "\") in a model given as text needs a base directory to resolve against");
    return Next::error;
  }
  path = relative[0] == '/' ? relative : *include_directory_ + relative;
  model_from_part = model_from_file_ * placement;
  return Next::include;
}

Result<Polygons> CaoFileReader::read_records(Polygons out, bool included) {
  Polygons own;
  if (!read_points(version_, own)) return error_;
  if (points_ == 0 && !included) return Error{path_, lines_[pos_ - 1].number, "the file defines no 3D point"};
  std::vector<std::pair<int, int>> lines;
  std::vector<PrimitiveAttributes> line_attributes;
  if (!read_lines(lines, line_attributes)) return error_;
  std::vector<bool> used(lines.size(), false);
  if (!read_faces_from_lines(lines, used, own)) return error_;
  for (size_t i = 0; i < lines.size(); ++i)
    if (!used[i]) {
      own.lines.push_back(lines[i]);
      own.line_attributes.push_back(line_attributes[i]);
    }
  if (!read_faces_from_points(own)) return error_;
  // Older files stop after the faces; otherwise the cylinder and circle counts follow.
  if (pos_ < lines_.size() && !read_cylinders(own)) return error_;
  if (pos_ < lines_.size() && !read_circles(own)) return error_;
  if (pos_ < lines_.size()) return Error{path_, lines_[pos_].number, "unexpected content after the circles section"};
  append_part(own, out);
  return out;
}

bool CaoFileReader::read_points(int version, Polygons& out) {
  if (!read_count("3D points", points_)) return false;
  const size_t needed = version == 2 ? 5 : 3;
  for (long k = 0; k < points_; ++k) {
    const TextLine* line = next("a 3D point");
    if (!line) return false;
    Vec3 p;
    if (line->tokens.size() < needed || !parse_real(line->tokens[0], p.x) || !parse_real(line->tokens[1], p.y) ||
        !parse_real(line->tokens[2], p.z))
      return fail(*line, "expected a 3D point: X Y Z" + std::string(version == 2 ? " i j" : ""));
    out.vertices.push_back(model_from_file_ * p);
  }
  return true;
}

bool CaoFileReader::read_lines(std::vector<std::pair<int, int>>& lines, std::vector<PrimitiveAttributes>& attributes) {
  return read_section("3D lines", "a 3D line", [&](const TextLine& line) {
    long a = 0, b = 0;
    if (!point_index(line, 0, a) || !point_index(line, 1, b))
      return fail(line, "expected a 3D line: two point indices in 0.." + std::to_string(points_ - 1));
    PrimitiveAttributes attribute;
    if (!attributes_of(line, 2, attribute)) return false;
    lines.emplace_back(static_cast<int>(a), static_cast<int>(b));
    attributes.push_back(attribute);
    return true;
  });
}

bool CaoFileReader::read_faces_from_lines(const std::vector<std::pair<int, int>>& lines, std::vector<bool>& used,
                                          Polygons& out) {
  return read_section("faces from lines", "a face from lines", [&](const TextLine& line) {
    std::vector<long> indices;
    PrimitiveAttributes attributes;
    if (!read_indexed(line, static_cast<long>(lines.size()), "line", indices, attributes)) return false;
    std::vector<std::pair<int, int>> segments;
    for (long index : indices) {
      segments.push_back(lines[index]);
      used[index] = true;
    }
    std::vector<int> loop;
    if (!chain_loop(segments, loop)) return fail(line, "the face's lines do not form one closed loop");
    out.faces.push_back(loop);
    out.face_attributes.push_back(attributes);
    return true;
  });
}

bool CaoFileReader::read_faces_from_points(Polygons& out) {
  return read_section("faces from points", "a face from points", [&](const TextLine& line) {
    std::vector<long> indices;
    PrimitiveAttributes attributes;
    if (!read_indexed(line, points_, "point", indices, attributes)) return false;
    if (indices.size() == 2) {  // as ViSP: a face of two points is one line, always visible
      // ViSP reads a face's minPolygonAreaThreshold only: the line keeps the general length.
      attributes.min_line_length.reset();
      attributes.min_polygon_area.reset();
      out.lines.emplace_back(static_cast<int>(indices[0]), static_cast<int>(indices[1]));
      out.line_attributes.push_back(attributes);
      return true;
    }
    out.faces.emplace_back(indices.begin(), indices.end());
    out.face_attributes.push_back(attributes);
    return true;
  });
}

bool CaoFileReader::read_cylinders(Polygons& out) {
  return read_section("3D cylinders", "a 3D cylinder", [&](const TextLine& line) {
    long a = 0, b = 0;
    CylinderRecord record;
    if (!point_index(line, 0, a) || !point_index(line, 1, b) || line.tokens.size() < 3 ||
        !parse_real(line.tokens[2], record.radius) || !(record.radius > real(0)))
      return fail(line, "expected a cylinder: two axis point indices in 0.." + std::to_string(points_ - 1) +
                            " and a positive radius");
    record.axis_a = static_cast<int>(a);
    record.axis_b = static_cast<int>(b);
    out.cylinders.push_back(record);
    return attributes_of(line, 3, out.cylinders.back().attributes);
  });
}

bool CaoFileReader::read_circles(Polygons& out) {
  return read_section("3D circles", "a 3D circle", [&](const TextLine& line) {
    long c = 0, a = 0, b = 0;
    CircleRecord record;
    if (!parse_real(line.tokens[0], record.radius) || !(record.radius > real(0)) || !point_index(line, 1, c) ||
        !point_index(line, 2, a) || !point_index(line, 3, b))
      return fail(line, "expected a circle: a positive radius, then the centre and two more points of its plane, "
                        "as indices in 0.." + std::to_string(points_ - 1));
    record.centre = static_cast<int>(c);
    record.plane_a = static_cast<int>(a);
    record.plane_b = static_cast<int>(b);
    out.circles.push_back(record);
    return attributes_of(line, 4, out.circles.back().attributes);
  });
}

/// Reads a model and its includes with an explicit stack of open files (no recursion, so a
/// long chain needs no call stack), each file once, within CaoIncludeLimits.
class CaoLoader {
 public:
  explicit CaoLoader(const CaoIncludeLimits& limits) : limits_(limits) {}

  Result<Polygons> load(const std::string& top) {
    if (std::optional<Error> refused = open(top, Se3())) return *refused;
    return read_open_files();
  }

  /// The same for a top model held in memory: `name` stands for its file in errors.
  Result<Polygons> load_text(const std::string& text, const std::string& name,
                             const std::optional<std::string>& base_directory) {
    if (text.size() > limits_.max_bytes)
      return Error{name, 0, "the model's text is more than " + std::to_string(limits_.max_bytes) + " bytes"};
    std::vector<TextLine> lines;
    split_text_lines(text, lines);
    std::optional<std::string> directory = base_directory;
    if (directory && !directory->empty() && directory->back() != '/') *directory += '/';
    push(CaoFileReader(name, std::move(directory), std::move(lines), Se3()), std::string(), text.size());
    return read_open_files();
  }

 private:
  Result<Polygons> read_open_files() {
    for (;;) {
      OpenFile& file = open_.back();
      std::string path;
      Se3 model_from_part;
      const CaoFileReader::Next next = file.reader.next_include(path, model_from_part);
      if (next == CaoFileReader::Next::error) return file.reader.error();
      if (next == CaoFileReader::Next::include) {
        if (std::optional<Error> refused = open(path, model_from_part)) return *refused;
        continue;
      }
      Result<Polygons> whole = file.reader.read_records(std::move(file.parts), file.included);
      if (!whole.ok()) return whole.error();
      on_chain_.erase(file.identity);
      open_.pop_back();
      if (open_.empty()) return whole;
      append_part(whole.value(), open_.back().parts);
      open_.back().included = true;
    }
  }

  struct OpenFile {
    CaoFileReader reader;
    std::string identity;
    Polygons parts;  ///< what its load() lines brought so far
    bool included = false;
  };

  /// Pushes `path` as the file being read, unless it is already in the model (skipped, as ViSP
  /// does) or refused.
  std::optional<Error> open(const std::string& path, const Se3& model_from_file) {
    const Result<InputFileIdentity> identity = input_file_identity(path);
    if (!identity.ok()) return unreadable(path, identity.error());
    const std::string& id = identity.value().canonical_path;
    if (on_chain_.count(id)) return refusal("load() makes a cycle: " + chain_to(path));
    if (loaded_.count(id)) return std::nullopt;
    if (static_cast<long>(open_.size()) >= limits_.max_depth)
      return refusal("the load() chain is deeper than " + std::to_string(limits_.max_depth) + " files: " + chain_to(path));
    if (static_cast<long>(loaded_.size()) >= limits_.max_files)
      return refusal("the model includes more than " + std::to_string(limits_.max_files) + " files; the next: " +
                     chain_to(path));
    if (identity.value().size > limits_.max_bytes - bytes_)
      return refusal("the model's files together are more than " + std::to_string(limits_.max_bytes) +
                     " bytes; the next: " + chain_to(path));
    std::vector<TextLine> lines;
    const Result<bool> read = read_text_lines(path, lines);
    if (!read.ok()) return unreadable(path, read.error());
    push(CaoFileReader(path, parent_directory(path), std::move(lines), model_from_file), id, identity.value().size);
    return std::nullopt;
  }
  /// `identity` is empty for a text in memory: no file's canonical path.
  void push(CaoFileReader reader, const std::string& identity, std::size_t size) {
    bytes_ += size;
    loaded_.insert(identity);
    on_chain_.insert(identity);
    open_.push_back(OpenFile{std::move(reader), identity, Polygons{}, false});
  }

  std::optional<Error> unreadable(const std::string& path, const Error& error) const {
    if (open_.empty()) return error;
    return refusal("cannot read the included file " + path + ": " + error.message + " (include chain: " +
                   chain_to(path) + ")");
  }
  /// An Error at the load() line being followed.
  Error refusal(const std::string& message) const {
    return Error{open_.back().reader.path(), open_.back().reader.load_line(), message};
  }
  /// "a.cao:3 -> b.cao:7 -> last": the load() line followed in each open file; a long chain
  /// keeps its first and last kEnds links and counts those between.
  std::string chain_to(const std::string& last) const {
    constexpr size_t kEnds = 3;
    std::string text;
    for (size_t i = 0; i < open_.size(); ++i) {
      if (open_.size() > 2 * kEnds + 1 && i == kEnds) {
        text += "(" + std::to_string(open_.size() - 2 * kEnds) + " more) -> ";
        i = open_.size() - kEnds - 1;
        continue;
      }
      text += open_[i].reader.path() + ":" + std::to_string(open_[i].reader.load_line()) + " -> ";
    }
    return text + last;
  }

  CaoIncludeLimits limits_;
  std::vector<OpenFile> open_;
  std::unordered_set<std::string> loaded_, on_chain_;  ///< canonical paths (empty: the text in memory)
  std::size_t bytes_ = 0;
};

}  // namespace

Result<Polygons> read_cao(const std::string& path, const CaoIncludeLimits& limits) {
  return CaoLoader(limits).load(path);
}

Result<Polygons> read_cao_text(const std::string& text, const std::string& name,
                               const std::optional<std::string>& base_directory, const CaoIncludeLimits& limits) {
  return CaoLoader(limits).load_text(text, name, base_directory);
}

}  // namespace edgetrack
