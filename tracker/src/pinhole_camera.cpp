// SPDX-License-Identifier: BSD-3-Clause
/// The pinhole camera and its reader for ViSP's XML camera block.
#include "edgetrack/pinhole_camera.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace edgetrack {
namespace {

/// The text between <tag> and </tag> inside `xml`, starting the search at `from`.
bool element_text(const std::string& xml, const std::string& tag, size_t from, size_t to, std::string& text) {
  const std::string open = "<" + tag + ">";
  const std::string close = "</" + tag + ">";
  const size_t start = xml.find(open, from);
  if (start == std::string::npos || start >= to) return false;
  const size_t end = xml.find(close, start);
  if (end == std::string::npos || end > to) return false;
  text = xml.substr(start + open.size(), end - start - open.size());
  return true;
}

int line_of(const std::string& text, size_t offset) {
  int line = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i)
    if (text[i] == '\n') ++line;
  return line;
}

}  // namespace

PinholeCamera PinholeCamera::scaled(int factor) const {
  // Pixel centres sit at integer coordinates, so pixel (0, 0) covers [-0.5, 0.5): in an image
  // `factor` times larger, the same ray lands at factor * (u + 0.5) - 0.5.
  const real shift = real(factor - 1) / 2;
  return {px * factor, py * factor, u0 * factor + shift, v0 * factor + shift, width * factor, height * factor};
}

Result<PinholeCamera> read_visp_camera_xml(const std::string& path, int width, int height) {
  std::ifstream in(path);
  if (!in) return Error{path, 0, "cannot open the file"};
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string xml = buffer.str();
  const size_t begin = xml.find("<camera>");
  if (begin == std::string::npos) return Error{path, 0, "no <camera> element"};
  const size_t end = xml.find("</camera>", begin);
  if (end == std::string::npos) return Error{path, line_of(xml, begin), "<camera> is not closed"};

  PinholeCamera camera;
  camera.width = width;
  camera.height = height;
  struct Field {
    const char* tag;
    real* value;
  } fields[] = {{"px", &camera.px}, {"py", &camera.py}, {"u0", &camera.u0}, {"v0", &camera.v0}};
  for (const Field& field : fields) {
    std::string text;
    if (!element_text(xml, field.tag, begin, end, text))
      return Error{path, line_of(xml, begin), std::string("<camera> has no <") + field.tag + ">"};
    char* stop = nullptr;
    const double parsed = std::strtod(text.c_str(), &stop);
    while (*stop == ' ' || *stop == '\t' || *stop == '\n' || *stop == '\r') ++stop;
    if (stop == text.c_str() || *stop != '\0')
      return Error{path, line_of(xml, xml.find(std::string("<") + field.tag + ">", begin)),
                   std::string("<") + field.tag + "> is not a number: '" + text + "'"};
    *field.value = real(parsed);  // set-up time conversion
  }
  std::string text;
  if (element_text(xml, "image_width", begin, end, text)) camera.width = std::atoi(text.c_str());
  if (element_text(xml, "image_height", begin, end, text)) camera.height = std::atoi(text.c_str());
  if (camera.px <= real(0) || camera.py <= real(0))
    return Error{path, line_of(xml, begin), "px and py must be positive"};
  if (camera.width <= 0 || camera.height <= 0) return Error{path, line_of(xml, begin), "the image size must be positive"};
  return camera;
}

}  // namespace edgetrack
