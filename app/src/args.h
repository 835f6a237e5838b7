// SPDX-License-Identifier: BSD-3-Clause
/// Command-line options of a subcommand: `--name value` and `--flag`, checked against the
/// options the subcommand declares, with typed getters that report bad values.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "edgetrack/result.h"

namespace edgetrack_app {

struct OptionSpec {
  const char* name;   ///< "--model"
  bool takes_value;   ///< false for flags
  const char* help;   ///< one line for the usage text
};

class Args {
 public:
  /// Parses argv[first..argc) against `specs`; unknown options and missing values are errors.
  static edgetrack::Result<Args> parse(int argc, char** argv, int first, const std::vector<OptionSpec>& specs);

  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::string text(const std::string& name, const std::string& fallback = "") const;
  /// The value as an integer / a number; an Error names the option and the value.
  edgetrack::Result<int> integer(const std::string& name, int fallback) const;
  /// A finite number: nan and inf are refused.
  edgetrack::Result<double> number(const std::string& name, double fallback) const;
  /// A frame number: -1 when the option is absent, an Error when it is negative.
  edgetrack::Result<int> frame_number(const std::string& name) const;
  /// A value "WIDTHxHEIGHT", each side 1..16384 and at most 64 M pixels (image_io.h).
  edgetrack::Result<bool> size(const std::string& name, int& width, int& height) const;

 private:
  std::map<std::string, std::string> values_;
};

/// The usage text of a subcommand.
std::string usage(const std::string& command, const std::string& synopsis, const std::vector<OptionSpec>& specs);

}  // namespace edgetrack_app
