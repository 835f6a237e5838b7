// SPDX-License-Identifier: BSD-3-Clause
/// Reading the <ecm> block of a ViSP XML configuration.
#include "me_config.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

int line_of(const std::string& text, size_t offset) {
  int line = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i)
    if (text[i] == '\n') ++line;
  return line;
}

/// Finds <parent>...<tag>value</tag> inside [from, to) and parses it; false when absent.
Result<bool> field(const std::string& xml, size_t from, size_t to, const std::string& parent, const std::string& tag,
                   const std::string& path, double& value) {
  size_t start = from;
  if (!parent.empty()) {
    start = xml.find("<" + parent + ">", from);
    if (start == std::string::npos || start >= to) return false;
    const size_t parent_end = xml.find("</" + parent + ">", start);
    if (parent_end != std::string::npos && parent_end < to) to = parent_end;
  }
  const size_t open = xml.find("<" + tag + ">", start);
  if (open == std::string::npos || open >= to) return false;
  const size_t text_begin = open + tag.size() + 2;
  const size_t close = xml.find("</" + tag + ">", text_begin);
  if (close == std::string::npos || close > to) return Error{path, line_of(xml, open), "<" + tag + "> is not closed"};
  const std::string text = xml.substr(text_begin, close - text_begin);
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  while (end && (*end == ' ' || *end == '\n' || *end == '\t' || *end == '\r')) ++end;
  if (end == text.c_str() || *end != '\0')
    return Error{path, line_of(xml, open), "<" + tag + "> is not a number: '" + text + "'"};
  if (value < 0) return Error{path, line_of(xml, open), "<" + tag + "> must not be negative"};
  return true;
}

}  // namespace

Result<EcmConfig> read_ecm_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Error{path, 0, "cannot open the file"};
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string xml = buffer.str();
  const size_t begin = xml.find("<ecm>");
  if (begin == std::string::npos) return Error{path, 0, "no <ecm> block (moving-edge parameters)"};
  const size_t end = xml.find("</ecm>", begin);
  if (end == std::string::npos) return Error{path, line_of(xml, begin), "<ecm> is not closed"};
  EcmConfig config;
  struct Entry {
    const char* parent;
    const char* tag;
    double value;
    bool found;
  } entries[] = {{"mask", "size", -1, false},          {"mask", "nb_mask", -1, false}, {"range", "tracking", -1, false},
                 {"contrast", "edge_threshold", -1, false}, {"contrast", "mu1", -1, false}, {"contrast", "mu2", -1, false},
                 {"sample", "step", -1, false}};
  for (Entry& e : entries) {
    auto got = field(xml, begin, end, e.parent, e.tag, path, e.value);
    if (!got.ok()) return got.error();
    e.found = got.value();
  }
  if (entries[0].found) config.mask_size = static_cast<int>(entries[0].value);
  if (entries[1].found) config.mask_number = static_cast<int>(entries[1].value);
  if (entries[2].found) config.range = static_cast<int>(entries[2].value);
  if (entries[3].found) config.threshold = entries[3].value;
  if (entries[4].found) config.mu1 = entries[4].value;
  if (entries[5].found) config.mu2 = entries[5].value;
  if (entries[6].found) config.sample_step = entries[6].value;
  return config;
}

Result<bool> apply_ecm_config(const EcmConfig& config, const std::string& path, edgetrack::TrackerParams& params) {
  // Limits: a mask needs a centre and neighbours and at most one orientation per degree
  // (upstream's angle step is 180 / n_mask, whole degrees); a range of 0 searches nothing.
  if (config.mask_size >= 0 && (config.mask_size < 3 || config.mask_size > 15))
    return Error{path, 0, "<mask><size> must be 3..15 pixels, not " + std::to_string(config.mask_size)};
  if (config.mask_number >= 0 && (config.mask_number < 1 || config.mask_number > 180))
    return Error{path, 0, "<mask><nb_mask> must be 1..180, not " + std::to_string(config.mask_number)};
  if (config.range == 0) return Error{path, 0, "<range><tracking> must be at least 1 pixel"};
  if (config.threshold == 0) return Error{path, 0, "<contrast><edge_threshold> must be positive"};
  if (config.sample_step == 0) return Error{path, 0, "<sample><step> must be positive"};
  if (config.mask_size > 0) params.me.setMaskSize(static_cast<unsigned>(config.mask_size));
  if (config.mask_number > 0) params.me.setMaskNumber(static_cast<unsigned>(config.mask_number));
  if (config.range > 0) params.me.setRange(static_cast<unsigned>(config.range));
  if (config.threshold > 0) params.me.setThreshold(real(config.threshold));
  if (config.sample_step > 0) params.sampling.step = real(config.sample_step);
  return true;
}

}  // namespace edgetrack_app
