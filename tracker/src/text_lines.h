// SPDX-License-Identifier: BSD-3-Clause
/// Line-oriented text input shared by the model readers: comments and Windows line ends removed,
/// words split, numbers parsed without locale surprises.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/result.h"
#include "real/real.h"

namespace edgetrack {

/// One non-empty line of a file with its comment (from '#') and any '\r' removed.
struct TextLine {
  int number = 0;                   ///< 1-based
  std::string text;                 ///< the line without its comment
  std::vector<std::string> tokens;  ///< `text` split at white space
};

/// Reads the non-empty lines of `path`; an Error naming it when it cannot be read (missing, not
/// a regular file, over read_input_text's size cap).
Result<bool> read_text_lines(const std::string& path, std::vector<TextLine>& lines);
/// The same for a text already in memory.
void split_text_lines(const std::string& text, std::vector<TextLine>& lines);

/// A whole token as a decimal integer or a real number.
bool parse_int(const std::string& token, long& value);
/// Model numbers (coordinates in metres, radii, thresholds) are finite and within a thousand
/// kilometres: a NaN or an overflowing vertex is refused at its line instead of breaking the
/// geometry built from it.
constexpr double kMaxModelNumber = 1e6;
bool parse_real(const std::string& token, real& value);

}  // namespace edgetrack
