// SPDX-License-Identifier: BSD-3-Clause
/// Option parsing for the subcommands.
#include "args.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <cstdlib>

#include "image_io.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

Result<Args> Args::parse(int argc, char** argv, int first, const std::vector<OptionSpec>& specs) {
  Args args;
  for (const OptionSpec& s : specs)
    if (!s.fallback.empty()) args.defaults_[s.name] = s.fallback;
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& s : specs)
      if (arg == s.name) spec = &s;
    if (!spec) return Error{"", 0, "unknown option '" + arg + "'"};
    if (!spec->value.empty()) {
      if (i + 1 >= argc) return Error{"", 0, "option " + arg + " needs a value (" + spec->value + ")"};
      args.values_[arg] = argv[++i];
    } else {
      args.values_[arg] = "";
    }
  }
  return args;
}

bool Args::value_of(const std::string& name, std::string& value) const {
  for (const auto* source : {&values_, &defaults_}) {
    const auto found = source->find(name);
    if (found != source->end()) {
      value = found->second;
      return true;
    }
  }
  return false;
}

std::string Args::text(const std::string& name) const {
  std::string value;
  value_of(name, value);
  return value;
}

Result<int> Args::integer(const std::string& name) const {
  std::string value;
  if (!value_of(name, value)) return Error{"", 0, "option " + name + " was not given and has no default"};
  char* end = nullptr;
  const long parsed = std::strtol(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0' || parsed < -1000000000L || parsed > 1000000000L)
    return Error{"", 0, "option " + name + " needs an integer, not '" + value + "'"};
  return static_cast<int>(parsed);
}

Result<double> Args::number(const std::string& name) const {
  std::string value;
  if (!value_of(name, value)) return Error{"", 0, "option " + name + " was not given and has no default"};
  char* end = nullptr;
  const double parsed = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(parsed))
    return Error{"", 0, "option " + name + " needs a finite number, not '" + value + "'"};
  return parsed;
}

Result<int> Args::frame_number(const std::string& name) const {
  if (!has(name)) return -1;
  auto value = integer(name);
  if (!value.ok()) return value;
  if (value.value() < 0)
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

namespace {

const OptionSpec kHelp = {"--help", "", "this text", ""};

/// "a, b or c" with `last` = "or".
std::string listed(const std::vector<std::string>& names, const std::string& last) {
  std::string text;
  for (size_t i = 0; i < names.size(); ++i) text += (i == 0 ? "" : i + 1 == names.size() ? " " + last + " " : ", ") + names[i];
  return text;
}

std::string left_column(const OptionSpec& spec) { return "  " + spec.name + (spec.value.empty() ? "" : " " + spec.value); }

}  // namespace

std::string usage(const CommandLine& line) {
  std::string text = "usage: edgetrack " + line.command + " " + line.synopsis + "\n";
  std::vector<OptionSpec> options = line.options;
  options.push_back(kHelp);
  size_t width = 0;
  for (const OptionSpec& s : options) width = std::max(width, left_column(s).size() + 2);
  for (const OptionSpec& s : options) {
    std::string left = left_column(s);
    left.resize(width, ' ');
    text += left + s.help + (s.fallback.empty() ? "" : " (default: " + s.fallback + ")") + "\n";
  }
  return text;
}

std::vector<std::string> missing_or_conflicting(const CommandLine& line, const Args& args) {
  std::vector<std::string> problems;
  for (const std::string& name : line.required)
    if (!args.has(name)) problems.push_back(name + " is required");
  for (const std::vector<std::string>& group : line.one_of) {
    std::vector<std::string> given;
    for (const std::string& name : group)
      if (args.has(name)) given.push_back(name);
    if (given.empty()) problems.push_back("one of " + listed(group, "or") + " is required");
    if (given.size() > 1) problems.push_back(listed(given, "and") + " cannot be given together: give one");
  }
  for (const auto& [option, needed] : line.needs)
    if (args.has(option) && !args.has(needed)) problems.push_back(option + " needs " + needed);
  return problems;
}

std::optional<int> parse_command_line(const CommandLine& line, int argc, char** argv, Args& args) {
  std::vector<OptionSpec> options = line.options;
  options.push_back(kHelp);
  auto parsed = Args::parse(argc, argv, 1, options);
  if (!parsed.ok()) {
    std::fprintf(stderr, "edgetrack %s: %s\n", line.command.c_str(), parsed.error().text().c_str());
    return 2;
  }
  args = std::move(parsed).value();
  if (args.has("--help")) {
    std::printf("%s", usage(line).c_str());
    return 0;
  }
  const std::vector<std::string> problems = missing_or_conflicting(line, args);
  if (problems.empty()) return std::nullopt;
  for (const std::string& problem : problems) std::fprintf(stderr, "edgetrack %s: %s\n", line.command.c_str(), problem.c_str());
  std::fprintf(stderr, "usage: edgetrack %s %s\n(edgetrack %s --help lists every option)\n", line.command.c_str(),
               line.synopsis.c_str(), line.command.c_str());
  return 2;
}

}  // namespace edgetrack_app
