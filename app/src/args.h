// SPDX-License-Identifier: BSD-3-Clause
/// The command line of a subcommand, declared once: its options (what each takes and its
/// default), the ones it requires, and the groups of which exactly one must be given. One
/// parse reads argv against it, prints `--help`, and names each missing or conflicting option;
/// typed getters read the values (or the declared defaults) and report bad ones.
#pragma once

#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "edgetrack/result.h"

namespace edgetrack_app {

/// One option: `{"--first", "N", "first frame number", "0"}`. Adding an option to a command is
/// one such line.
struct OptionSpec {
  std::string name;      ///< "--model"
  std::string value;     ///< what it takes, for --help: FILE, N, MIN:MAX, DIR, PATTERN...; empty for a flag
  std::string help;      ///< one line for the usage text
  /// The value the getters read when the option is absent, shown in --help as its default. A
  /// default that is a rule rather than a value is said in `help`, "(default: ...)".
  std::string fallback;
};

/// A subcommand's command line.
struct CommandLine {
  std::string command;   ///< "track"
  std::string synopsis;  ///< the usage line after "edgetrack track"
  std::vector<OptionSpec> options;  ///< `--help` is added by the parse
  std::vector<std::string> required;                        ///< each must be given
  std::vector<std::vector<std::string>> one_of;             ///< exactly one of each group must be given
  std::vector<std::pair<std::string, std::string>> needs;  ///< the first only together with the second
};

class Args {
 public:
  /// Parses argv[first..argc) against `specs`; unknown options and missing values are errors.
  static edgetrack::Result<Args> parse(int argc, char** argv, int first, const std::vector<OptionSpec>& specs);

  /// Whether the option was given on the command line (a default does not count).
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  /// The value given, else the option's declared default, else "".
  std::string text(const std::string& name) const;
  /// The value (given, else the declared default) as an integer / a number; an Error names the
  /// option and the value, or says that the option was not given and has no default.
  edgetrack::Result<int> integer(const std::string& name) const;
  /// A finite number: nan and inf are refused.
  edgetrack::Result<double> number(const std::string& name) const;
  /// A frame number: -1 when the option is absent, an Error when it is negative.
  edgetrack::Result<int> frame_number(const std::string& name) const;
  /// A value "WIDTHxHEIGHT", each side 1..16384 and at most 64 M pixels (image_io.h).
  edgetrack::Result<bool> size(const std::string& name, int& width, int& height) const;

 private:
  /// The value given, else the declared default; false when there is neither.
  bool value_of(const std::string& name, std::string& value) const;
  std::map<std::string, std::string> values_;
  std::map<std::string, std::string> defaults_;
};

/// The `--help` text of a command: the synopsis, then one line per option with what it takes
/// and its default.
std::string usage(const CommandLine& line);

/// The problems of a parsed command line, one line each: a required option missing, a group
/// with none or several given, an option given without the one it needs.
std::vector<std::string> missing_or_conflicting(const CommandLine& line, const Args& args);

/// Parses argv[1..) against `line` into `args`. Returns the exit status when the command stops
/// here: 0 after printing `--help` to stdout; 2 after an unknown option, a missing value, or a
/// missing or conflicting option, each one line on stderr naming it, then the synopsis.
std::optional<int> parse_command_line(const CommandLine& line, int argc, char** argv, Args& args);

/// OPTION NAME=VALUE,...: each setting through `set`, which returns what is wrong or nothing.
template <typename Set>
edgetrack::Result<bool> apply_named_settings(const char* option, const std::string& text, Set set) {
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(start, end - start);
    const size_t equals = item.find('=');
    char* stop = nullptr;
    const double value = equals == std::string::npos ? 0 : std::strtod(item.c_str() + equals + 1, &stop);
    if (equals == std::string::npos || equals + 1 == item.size() || *stop != '\0')
      return edgetrack::Error{"", 0, std::string(option) + " takes NAME=VALUE pairs separated by commas, not '" + item + "'"};
    const std::string problem = set(item.substr(0, equals), value);
    if (!problem.empty()) return edgetrack::Error{"", 0, std::string(option) + " " + item + ": " + problem};
    start = end + 1;
  }
  return true;
}

}  // namespace edgetrack_app
