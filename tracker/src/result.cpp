// SPDX-License-Identifier: BSD-3-Clause
/// Formatting of errors.
#include "edgetrack/result.h"

namespace edgetrack {

std::string Error::text() const {
  if (file.empty()) return message;
  if (line > 0) return file + ":" + std::to_string(line) + ": " + message;
  return file + ": " + message;
}

}  // namespace edgetrack
