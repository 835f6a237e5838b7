// SPDX-License-Identifier: BSD-3-Clause
/// Numbers read from text files, checked where they are read: each field has a documented range,
/// and a value that is not a number, not finite, out of its range or (for whole numbers)
/// fractional or overflowing is refused with the file, the line and the field.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/result.h"

namespace edgetrack {

/// The name and the inclusive range of one field, as the refusal states them.
struct FieldRange {
  const char* field;
  double low;
  double high;
};

/// `text`, whole, as a finite number inside `range`.
Result<double> parse_field(const std::string& text, const FieldRange& range, const std::string& file, int line);
/// `text`, whole, as a whole number inside `range` (no fraction, no exponent, no overflow).
Result<long long> parse_whole_field(const std::string& text, const FieldRange& range, const std::string& file,
                                    int line);

/// `value` as a std::ostream prints a double by default (printf's "%g"), with no stream or locale:
/// the numbers of the settings' and inputs' refusals.
std::string number_text(double value);

/// One white-space separated word of a text file, with its 1-based line.
struct Word {
  std::string text;
  int line = 0;
};

/// The words of `path` (read_input_text's bounds), `#` starting a comment to the end of a line.
Result<std::vector<Word>> read_words(const std::string& path);
/// The same for a text already in memory.
std::vector<Word> words_of_text(const std::string& text);

}  // namespace edgetrack
