// SPDX-License-Identifier: BSD-3-Clause
/// Reading model files line by line.
#include "text_lines.h"

#include "edgetrack/input_file.h"

#include <cstdlib>
#include <cmath>
#include <sstream>

namespace edgetrack {

Result<bool> read_text_lines(const std::string& path, std::vector<TextLine>& lines) {
  auto whole = read_input_text(path);
  if (!whole.ok()) return whole.error();
  split_text_lines(whole.value(), lines);
  return true;
}

void split_text_lines(const std::string& whole, std::vector<TextLine>& lines) {
  std::istringstream in(whole);
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    const size_t hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    TextLine line;
    line.number = number;
    std::string word;
    while (words >> word) line.tokens.push_back(word);
    line.text = text;
    if (!line.tokens.empty()) lines.push_back(std::move(line));
  }
}

bool parse_int(const std::string& token, long& value) {
  char* end = nullptr;
  value = std::strtol(token.c_str(), &end, 10);
  return !token.empty() && *end == '\0';
}

bool parse_real(const std::string& token, real& value) {
  char* end = nullptr;
  const double parsed = std::strtod(token.c_str(), &end);
  if (token.empty() || *end != '\0' || !std::isfinite(parsed) || std::fabs(parsed) > kMaxModelNumber) return false;
  value = real(parsed);  // set-up time conversion, never in the frame loop
  return true;
}

}  // namespace edgetrack
