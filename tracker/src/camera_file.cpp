// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's and OpenCV's calibration files. Facts from ViSP 3.5's vpXmlParserCamera (a <root> of
/// <camera> elements, each with <name>, <image_width>, <image_height> and <model>s whose <type>
/// is perspectiveProjWithoutDistortion or perspectiveProjWithDistortion with <px>, <py>, <u0>,
/// <v0> and for the latter <kud>, <kdu>) and OpenCV's calibration sample (camera_matrix and
/// distortion_coefficients as opencv-matrix with rows, cols, dt and data, in YAML or XML).
#include "edgetrack/camera_file.h"

#include <cstdio>
#include <vector>

#include "edgetrack/input_file.h"
#include "edgetrack/number_text.h"
#include "edgetrack/tracker_inputs.h"
#include "edgetrack/xml_document.h"

namespace edgetrack {
namespace {

// The tracker's own limits (tracker_inputs.h, image_limits.h), so that what reads is tracked.
constexpr FieldRange kFocal{"focal length (pixels)", 1e-3, kMaxFocalPx};
constexpr FieldRange kCentre{"principal point (pixels)", -kMaxPrincipalPointPx, kMaxPrincipalPointPx};
constexpr FieldRange kSize{"image size (pixels)", 1, kMaxImageSide};
constexpr FieldRange kCoefficient{"distortion coefficient", -kMaxLensCoefficient, kMaxLensCoefficient};
constexpr FieldRange kMatrixSize{"matrix size", 1, 16};

/// A number already read (a matrix entry) refused at `line` when outside `range`.
Result<bool> check_range(double value, const FieldRange& range, const std::string& path, int line) {
  if (value >= range.low && value <= range.high) return true;
  char text[160];
  std::snprintf(text, sizeof text, "%s is out of its range (%.10g..%.10g): %.10g", range.field, range.low, range.high,
                value);
  return Error{path, line, text};
}

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

/// The image size the file gives, checked against the one chosen (0: any).
Result<bool> check_size(const std::string& path, int line, int width, int height, const CameraChoice& choice) {
  if (width == 0 && choice.width == 0) return Error{path, line, "gives no image size (image_width, image_height)"};
  if (choice.width > 0 && width > 0 && (width != choice.width || height != choice.height))
    return Error{path, line,
                 "is a calibration of " + size_text(width, height) + " images, not " + size_text(choice.width, choice.height)};
  return true;
}

// ---- ViSP ------------------------------------------------------------------------------------

const XmlElement* child(const XmlElement& e, const char* name) {
  for (const XmlElement& c : e.children)
    if (c.name == name) return &c;
  return nullptr;
}

Result<double> visp_value(const std::string& path, const XmlElement& model, const char* name, const FieldRange& range) {
  const XmlElement* e = child(model, name);
  if (e == nullptr) return Error{path, model.line, std::string("<model> has no <") + name + ">"};
  return parse_field(e->text, range, path, e->line);
}

Result<PinholeCamera> visp_camera(const std::string& path, const XmlElement& root, const CameraChoice& choice) {
  std::string seen;  // what the file holds, for the refusal
  for (const XmlElement& camera : root.children) {
    if (camera.name != "camera") continue;
    const XmlElement* name = child(camera, "name");
    const std::string camera_name = name ? name->text : "";
    long long width = 0, height = 0;
    for (const char* field : {"image_width", "image_height"}) {
      const XmlElement* e = child(camera, field);
      if (e == nullptr) continue;
      auto got = parse_whole_field(e->text, kSize, path, e->line);
      if (!got.ok()) return got.error();
      (field[6] == 'w' ? width : height) = got.value();
    }
    seen += (seen.empty() ? "" : ", ") + ("'" + camera_name + "' " + size_text(int(width), int(height)));
    if (!choice.name.empty() && camera_name != choice.name) continue;
    if (choice.width > 0 && width > 0 && (width != choice.width || height != choice.height)) continue;
    // The distorted model when there is one (the frames are a real lens's), else the pinhole.
    const XmlElement* chosen = nullptr;
    for (const XmlElement& model : camera.children) {
      if (model.name != "model") continue;
      const XmlElement* type = child(model, "type");
      if (type == nullptr) return Error{path, model.line, "<model> has no <type>"};
      if (type->text == "perspectiveProjWithDistortion") chosen = &model;
      else if (type->text == "perspectiveProjWithoutDistortion" && chosen == nullptr) chosen = &model;
      else if (type->text != "perspectiveProjWithoutDistortion")
        return Error{path, type->line, "projection model '" + type->text +
                                            "' is not modelled (perspectiveProjWithoutDistortion and "
                                            "perspectiveProjWithDistortion are)"};
    }
    if (chosen == nullptr) return Error{path, camera.line, "<camera> '" + camera_name + "' has no <model>"};
    auto sized = check_size(path, camera.line, int(width), int(height), choice);
    if (!sized.ok()) return sized.error();
    double values[6] = {0, 0, 0, 0, 0, 0};
    const bool distorted = child(*chosen, "type")->text == "perspectiveProjWithDistortion";
    const char* names[6] = {"px", "py", "u0", "v0", "kud", "kdu"};
    const FieldRange* ranges[6] = {&kFocal, &kFocal, &kCentre, &kCentre, &kCoefficient, &kCoefficient};
    for (int k = 0; k < (distorted ? 6 : 4); ++k) {
      auto got = visp_value(path, *chosen, names[k], *ranges[k]);
      if (!got.ok()) return got.error();
      values[k] = got.value();
    }
    PinholeCamera result{real(values[0]), real(values[1]), real(values[2]), real(values[3]),
                         width > 0 ? int(width) : choice.width, height > 0 ? int(height) : choice.height};
    if (distorted) {
      result.lens.model = LensModel::kVisp;
      result.lens.kud = real(values[4]);
      result.lens.kdu = real(values[5]);
    }
    return result;
  }
  std::string wanted = choice.name.empty() ? "a camera" : "camera '" + choice.name + "'";
  if (choice.width > 0) wanted += " of " + size_text(choice.width, choice.height);
  return Error{path, root.line, "has no " + wanted + (seen.empty() ? " (no <camera> at all)" : " (it has " + seen + ")")};
}

// ---- OpenCV ----------------------------------------------------------------------------------

/// An opencv-matrix, or an image size, as read from either syntax.
struct Matrix {
  int line = 0;
  long long rows = 0, cols = 0;
  std::vector<double> data;
};

struct OpenCvFields {
  int root_line = 1;
  long long width = 0, height = 0;
  int size_line = 0;
  Matrix camera_matrix, distortion;
};

/// The numbers of a data list ("[ 1., 2.,\n 3. ]" in YAML, "1. 2. 3." in XML), each refused at its line.
Result<bool> read_numbers(const std::string& path, const std::string& text, int first_line, std::vector<double>& out) {
  int line = first_line;
  std::string word;
  const auto flush = [&]() -> Result<bool> {
    if (word.empty()) return true;
    auto got = parse_field(word, FieldRange{"matrix entry", -1e9, 1e9}, path, line);
    word.clear();
    if (!got.ok()) return got.error();
    out.push_back(got.value());
    return true;
  };
  for (char c : text) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '[' || c == ']') {
      auto flushed = flush();
      if (!flushed.ok()) return flushed;
      if (c == '\n') ++line;
    } else {
      word += c;
    }
  }
  return flush();
}

Result<bool> check_matrix(const std::string& path, const char* name, const Matrix& m) {
  if (m.line == 0) return Error{path, 1, std::string("has no ") + name};
  if (m.rows * m.cols != static_cast<long long>(m.data.size()))
    return Error{path, m.line, std::string(name) + " has " + std::to_string(m.data.size()) + " entries, not rows x cols = " +
                                   std::to_string(m.rows * m.cols)};
  return true;
}

Result<bool> opencv_xml_fields(const std::string& path, const XmlElement& root, OpenCvFields& f) {
  f.root_line = root.line;
  for (const XmlElement& e : root.children) {
    if (e.name == "image_width" || e.name == "image_height") {
      auto got = parse_whole_field(e.text, kSize, path, e.line);
      if (!got.ok()) return got.error();
      (e.name == "image_width" ? f.width : f.height) = got.value();
      f.size_line = e.line;
    } else if (e.name == "camera_matrix" || e.name == "distortion_coefficients") {
      Matrix& m = e.name == "camera_matrix" ? f.camera_matrix : f.distortion;
      m.line = e.line;
      for (const XmlElement& c : e.children) {
        if (c.name == "rows" || c.name == "cols") {
          auto got = parse_whole_field(c.text, kMatrixSize, path, c.line);
          if (!got.ok()) return got.error();
          (c.name == "rows" ? m.rows : m.cols) = got.value();
        } else if (c.name == "data") {
          auto read = read_numbers(path, c.text, c.line, m.data);
          if (!read.ok()) return read;
        }
      }
    }
  }
  return true;
}

/// A YAML line's indentation, key and value ("key: value"); false when it is not one.
bool yaml_pair(const std::string& line, size_t& indent, std::string& key, std::string& value) {
  indent = line.find_first_not_of(' ');
  const size_t colon = line.find(':', indent);
  if (indent == std::string::npos || colon == std::string::npos) return false;
  key = line.substr(indent, colon - indent);
  const size_t start = line.find_first_not_of(' ', colon + 1);
  value = start == std::string::npos ? "" : line.substr(start);
  while (!value.empty() && (value.back() == '\r' || value.back() == ' ')) value.pop_back();
  return true;
}

Result<bool> opencv_yaml_fields(const std::string& path, const std::string& text, OpenCvFields& f) {
  std::vector<std::string> lines;
  for (size_t begin = 0; begin <= text.size();) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  Matrix* matrix = nullptr;  // the top-level matrix whose fields the indented lines give
  for (size_t i = 1; i < lines.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    std::string line = lines[i];
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#' || line == "---" || line.find_first_not_of(' ') == std::string::npos) continue;
    size_t indent;
    std::string key, value;
    const bool pair = yaml_pair(line, indent, key, value);
    if (indent == 0) {
      matrix = nullptr;
      if (!pair) return Error{path, number, "is not 'key: value': '" + line + "'"};
      if (key == "image_width" || key == "image_height") {
        auto got = parse_whole_field(value, kSize, path, number);
        if (!got.ok()) return got.error();
        (key == "image_width" ? f.width : f.height) = got.value();
        f.size_line = number;
      } else if (key == "camera_matrix" || key == "distortion_coefficients") {
        if (value != "!!opencv-matrix") return Error{path, number, key + " is not an !!opencv-matrix"};
        matrix = key == "camera_matrix" ? &f.camera_matrix : &f.distortion;
        matrix->line = number;
      }
      continue;
    }
    if (matrix == nullptr || !pair) continue;  // inside a field this reader does not need
    if (key == "rows" || key == "cols") {
      auto got = parse_whole_field(value, kMatrixSize, path, number);
      if (!got.ok()) return got.error();
      (key == "rows" ? matrix->rows : matrix->cols) = got.value();
    } else if (key == "data") {
      // The list runs to its ']', over as many lines as it takes.
      std::string list = value;
      size_t last = i;
      while (list.find(']') == std::string::npos && last + 1 < lines.size()) list += "\n" + lines[++last];
      if (list.empty() || list[0] != '[' || list.find(']') == std::string::npos)
        return Error{path, number, "data is not a [ ... ] list"};
      auto read = read_numbers(path, list, number, matrix->data);
      if (!read.ok()) return read;
      i = last;
    }
  }
  return true;
}

Result<PinholeCamera> opencv_camera(const std::string& path, const OpenCvFields& f, const CameraChoice& choice) {
  auto sized = check_size(path, f.size_line ? f.size_line : f.root_line, int(f.width), int(f.height), choice);
  if (!sized.ok()) return sized.error();
  for (const auto& [name, m] : {std::pair<const char*, const Matrix&>{"camera_matrix", f.camera_matrix},
                                {"distortion_coefficients", f.distortion}}) {
    auto checked = check_matrix(path, name, m);
    if (!checked.ok()) return checked.error();
  }
  const std::vector<double>& k = f.camera_matrix.data;
  if (f.camera_matrix.rows != 3 || f.camera_matrix.cols != 3)
    return Error{path, f.camera_matrix.line, "camera_matrix is not 3 x 3"};
  if (k[1] != 0 || k[3] != 0 || k[6] != 0 || k[7] != 0 || k[8] != 1)
    return Error{path, f.camera_matrix.line,
                 "camera_matrix is not [fx 0 cx; 0 fy cy; 0 0 1] (a skew is not modelled)"};
  const int line = f.camera_matrix.line;
  for (const auto& [value, range] : {std::pair<double, FieldRange>{k[0], kFocal}, {k[4], kFocal}, {k[2], kCentre},
                                     {k[5], kCentre}}) {
    auto checked = check_range(value, range, path, line);
    if (!checked.ok()) return checked.error();
  }
  const std::vector<double>& d = f.distortion.data;
  const size_t n = d.size();
  if (n != 4 && n != 5 && n != 8 && n != 12 && n != 14)
    return Error{path, f.distortion.line,
                 "distortion_coefficients has " + std::to_string(n) + " entries, not 4, 5, 8, 12 or 14"};
  for (size_t i = 5; i < n; ++i)
    if (d[i] != 0)
      return Error{path, f.distortion.line,
                   "distortion_coefficients' rational (k4, k5, k6), thin-prism (s1..s4) and tilt terms are not modelled: "
                   "calibrate without CALIB_RATIONAL_MODEL, CALIB_THIN_PRISM_MODEL and CALIB_TILTED_MODEL"};
  for (size_t i = 0; i < n && i < 5; ++i) {
    auto checked = check_range(d[i], kCoefficient, path, f.distortion.line);
    if (!checked.ok()) return checked.error();
  }
  PinholeCamera camera{real(k[0]), real(k[4]), real(k[2]), real(k[5]), int(f.width), int(f.height)};
  camera.lens.model = LensModel::kOpenCv;
  camera.lens.k1 = real(d[0]);
  camera.lens.k2 = real(d[1]);
  camera.lens.p1 = real(d[2]);
  camera.lens.p2 = real(d[3]);
  camera.lens.k3 = real(n >= 5 ? d[4] : 0.0);
  return camera;
}

}  // namespace

Result<PinholeCamera> read_camera_file(const std::string& path, const CameraChoice& choice) {
  auto text = read_input_text(path);
  if (!text.ok()) return text.error();
  const std::string& s = text.value();
  const size_t first = s.find_first_not_of(" \t\r\n");
  if (s.compare(0, 5, "%YAML") == 0) {
    OpenCvFields fields;
    auto read = opencv_yaml_fields(path, s, fields);
    if (!read.ok()) return read.error();
    return opencv_camera(path, fields, choice);
  }
  if (first == std::string::npos || s[first] != '<')
    return Error{path, 1, "is neither a ViSP camera file (XML) nor an OpenCV calibration file (YAML or XML)"};
  auto xml = parse_xml(s, path);
  if (!xml.ok()) return xml.error();
  const XmlElement& root = xml.value();
  if (root.name == "root") return visp_camera(path, root, choice);
  if (root.name == "opencv_storage") {
    OpenCvFields fields;
    auto read = opencv_xml_fields(path, root, fields);
    if (!read.ok()) return read.error();
    return opencv_camera(path, fields, choice);
  }
  return Error{path, root.line, "root <" + root.name + "> is neither ViSP's <root> nor OpenCV's <opencv_storage>"};
}

}  // namespace edgetrack
