// SPDX-License-Identifier: BSD-3-Clause
/// Line-oriented text input shared by the model readers: comments and Windows line ends removed,
/// words split, numbers parsed without locale surprises.
#pragma once

#include <string>
#include <vector>

#include "real/real.h"

namespace edgetrack {

/// One non-empty line of a file with its comment (from '#') and any '\r' removed.
struct TextLine {
  int number = 0;                   ///< 1-based
  std::string text;                 ///< the line without its comment
  std::vector<std::string> tokens;  ///< `text` split at white space
};

/// Reads the non-empty lines of `path`; false when the file cannot be opened.
bool read_text_lines(const std::string& path, std::vector<TextLine>& lines);

/// A whole token as a decimal integer or a real number.
bool parse_int(const std::string& token, long& value);
bool parse_real(const std::string& token, real& value);

}  // namespace edgetrack
