// SPDX-License-Identifier: BSD-3-Clause
/// Option parsing for the subcommands.
#include "args.h"

#include <cstdio>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "image_io.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

Result<Args> Args::parse(int argc, char** argv, int first, const std::vector<OptionSpec>& specs) {
  Args args;
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& s : specs)
      if (arg == s.name) spec = &s;
    if (!spec) return Error{"", 0, "unknown option '" + arg + "'"};
    if (spec->takes_value) {
      if (i + 1 >= argc) return Error{"", 0, "option " + arg + " needs a value"};
      args.values_[arg] = argv[++i];
    } else {
      args.values_[arg] = "";
    }
  }
  return args;
}

std::string Args::text(const std::string& name, const std::string& fallback) const {
  const auto found = values_.find(name);
  return found == values_.end() ? fallback : found->second;
}

Result<int> Args::integer(const std::string& name, int fallback) const {
  if (!has(name)) return fallback;
  const std::string& value = values_.at(name);
  char* end = nullptr;
  const long parsed = std::strtol(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0' || parsed < -1000000000L || parsed > 1000000000L)
    return Error{"", 0, "option " + name + " needs an integer, not '" + value + "'"};
  return static_cast<int>(parsed);
}

Result<double> Args::number(const std::string& name, double fallback) const {
  if (!has(name)) return fallback;
  const std::string& value = values_.at(name);
  char* end = nullptr;
  const double parsed = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(parsed))
    return Error{"", 0, "option " + name + " needs a finite number, not '" + value + "'"};
  return parsed;
}

Result<int> Args::frame_number(const std::string& name) const {
  auto value = integer(name, -1);
  if (!value.ok()) return value;
  if (has(name) && value.value() < 0)
    return Error{"", 0, "option " + name + " needs a frame number (0 or more), not '" + values_.at(name) + "'"};
  return value;
}

Result<bool> Args::size(const std::string& name, int& width, int& height) const {
  if (!has(name)) return false;
  const std::string& value = values_.at(name);
  // strtoll, not sscanf's %d, so that a side too large for int is refused rather than undefined.
  const char* text = value.c_str();
  char* x = nullptr;
  char* end = nullptr;
  const long long w = std::isdigit(static_cast<unsigned char>(text[0])) ? std::strtoll(text, &x, 10) : 0;
  const long long h = x && *x == 'x' && std::isdigit(static_cast<unsigned char>(x[1])) ? std::strtoll(x + 1, &end, 10) : 0;
  if (w <= 0 || h <= 0 || !end || *end != '\0')
    return Error{"", 0, "option " + name + " needs WIDTHxHEIGHT, not '" + value + "'"};
  if (!usable_image_size(w, h))
    return Error{"", 0, "option " + name + " asks for " + value + ": sides must be at most " +
                            std::to_string(kMaxImageSide) + " pixels and the image at most " +
                            std::to_string(kMaxImagePixels >> 20) + " M pixels"};
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

std::string usage(const std::string& command, const std::string& synopsis, const std::vector<OptionSpec>& specs) {
  std::string text = "usage: edgetrack " + command + " " + synopsis + "\n";
  for (const OptionSpec& s : specs) {
    std::string left = std::string("  ") + s.name + (s.takes_value ? " V" : "");
    if (left.size() < 24) left.resize(24, ' ');
    text += left + " " + s.help + "\n";
  }
  return text;
}

}  // namespace edgetrack_app
