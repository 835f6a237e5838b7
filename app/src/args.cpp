// SPDX-License-Identifier: BSD-3-Clause
/// Option parsing for the subcommands.
#include "args.h"

#include <cstdio>
#include <cstdlib>

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
  if (value.empty() || *end != '\0') return Error{"", 0, "option " + name + " needs a number, not '" + value + "'"};
  return parsed;
}

Result<bool> Args::size(const std::string& name, int& width, int& height) const {
  if (!has(name)) return false;
  const std::string& value = values_.at(name);
  int w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(value.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w <= 0 || h <= 0)
    return Error{"", 0, "option " + name + " needs WIDTHxHEIGHT, not '" + value + "'"};
  width = w;
  height = h;
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
