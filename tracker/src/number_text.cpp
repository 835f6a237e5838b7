// SPDX-License-Identifier: BSD-3-Clause
/// Checked numbers from text.
#include "edgetrack/number_text.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "edgetrack/input_file.h"

namespace edgetrack {
namespace {

std::string range_text(const FieldRange& range) {
  char text[96];
  std::snprintf(text, sizeof text, "%.10g..%.10g", range.low, range.high);
  return text;
}

Error refusal(const std::string& file, int line, const FieldRange& range, const std::string& text, const char* why) {
  return Error{file, line, std::string(range.field) + " " + why + " (" + range_text(range) + "): '" + text + "'"};
}

}  // namespace

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

Result<double> parse_field(const std::string& text, const FieldRange& range, const std::string& file, int line) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end == begin || *end != '\0') return refusal(file, line, range, text, "is not a number");
  if (!std::isfinite(value) || errno == ERANGE) return refusal(file, line, range, text, "is not a finite number");
  if (value < range.low || value > range.high) return refusal(file, line, range, text, "is out of its range");
  return value;
}

Result<long long> parse_whole_field(const std::string& text, const FieldRange& range, const std::string& file,
                                    int line) {
  size_t i = text.size() > 0 && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (i == text.size()) return refusal(file, line, range, text, "is not a whole number");
  for (size_t k = i; k < text.size(); ++k)
    if (text[k] < '0' || text[k] > '9') return refusal(file, line, range, text, "is not a whole number");
  errno = 0;
  const long long value = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE || static_cast<double>(value) < range.low || static_cast<double>(value) > range.high)
    return refusal(file, line, range, text, "is out of its range");
  return value;
}

Result<std::vector<Word>> read_words(const std::string& path) {
  auto text = read_input_text(path);
  if (!text.ok()) return text.error();
  return words_of_text(text.value());
}

std::vector<Word> words_of_text(const std::string& s) {
  std::vector<Word> words;
  int line = 1;
  for (size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (c == '#') {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++i;
    } else {
      const size_t start = i;
      while (i < s.size() && s[i] != '\n' && s[i] != '#' && s[i] != ' ' && s[i] != '\t' && s[i] != '\r' &&
             s[i] != '\f' && s[i] != '\v')
        ++i;
      words.push_back({s.substr(start, i - start), line});
    }
  }
  return words;
}

}  // namespace edgetrack
