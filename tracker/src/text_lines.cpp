// SPDX-License-Identifier: BSD-3-Clause
/// Reading model files line by line.
#include "text_lines.h"

#include "edgetrack/input_file.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace edgetrack {

Result<bool> read_text_lines(const std::string& path, std::vector<TextLine>& lines) {
  auto whole = read_input_text(path);
  if (!whole.ok()) return whole.error();
  split_text_lines(whole.value(), lines);
  return true;
}

void split_text_lines(const std::string& whole, std::vector<TextLine>& lines) {
  int number = 0;
  // Lines as std::getline cuts them (no empty line after a final newline), words as >> reads
  // them (the C locale's white space), with no stream: a firmware reading a model links no locale.
  for (size_t start = 0; start < whole.size();) {
    size_t end = whole.find('\n', start);
    if (end == std::string::npos) end = whole.size();
    std::string text = whole.substr(start, end - start);
    start = end + 1;
    ++number;
    const size_t hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    TextLine line;
    line.number = number;
    for (size_t i = 0; i < text.size();) {
      if (std::isspace(static_cast<unsigned char>(text[i]))) {
        ++i;
        continue;
      }
      const size_t word = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      line.tokens.push_back(text.substr(word, i - word));
    }
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
