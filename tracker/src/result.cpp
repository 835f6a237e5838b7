// SPDX-License-Identifier: BSD-3-Clause
/// Formatting of errors, and the stop of value() on one.
#include "edgetrack/result.h"

#include <cstdio>
#include <cstdlib>

namespace edgetrack {

std::string Error::text() const {
  if (file.empty()) return message;
  if (line > 0) return file + ":" + std::to_string(line) + ": " + message;
  return file + ": " + message;
}

void stop_on_error_value(const Error& error) {
  std::fprintf(stderr, "edgetrack: value() of a failed result: %s\n", error.text().c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace edgetrack
