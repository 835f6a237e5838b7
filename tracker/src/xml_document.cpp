// SPDX-License-Identifier: BSD-3-Clause
/// A small recursive-descent XML reader: enough for ViSP's configuration files.
#include "edgetrack/xml_document.h"

#include <cstring>

#include "edgetrack/input_file.h"

namespace edgetrack {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string trimmed(const std::string& s) {
  size_t begin = 0, end = s.size();
  while (begin < end && is_space(s[begin])) ++begin;
  while (end > begin && is_space(s[end - 1])) --end;
  return s.substr(begin, end - begin);
}

void append_utf8(unsigned long code, std::string& out) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

/// A code point XML allows in a document (XML 1.0, Char).
bool is_xml_char(unsigned long code) {
  return code == 0x9 || code == 0xA || code == 0xD || (code >= 0x20 && code <= 0xD7FF) ||
         (code >= 0xE000 && code <= 0xFFFD) || (code >= 0x10000 && code <= 0x10FFFF);
}

/// The document as UTF-8, as an XML parser detects its encoding: a UTF-8 byte-order mark is
/// dropped; UTF-16 (little or big endian, by its byte-order mark or by a first '<' of two bytes)
/// is converted.
Result<std::string> as_utf8(const std::string& bytes, const std::string& source) {
  const auto byte = [&](size_t i) { return static_cast<unsigned char>(bytes[i]); };
  if (bytes.size() >= 3 && byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) return bytes.substr(3);
  bool little = false;
  size_t start = 0;
  if (bytes.size() >= 2 && ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF))) {
    little = byte(0) == 0xFF;
    start = 2;
  } else if (bytes.size() >= 2 && ((byte(0) == '<' && byte(1) == 0) || (byte(0) == 0 && byte(1) == '<'))) {
    little = byte(0) == '<';
  } else {
    return bytes;
  }
  std::string out;
  int line = 1;
  const auto unit = [&](size_t i) -> unsigned long { return little ? byte(i) | byte(i + 1) << 8 : byte(i) << 8 | byte(i + 1); };
  for (size_t i = start; i < bytes.size(); i += 2) {
    if (i + 1 >= bytes.size()) return Error{source, line, "UTF-16 text ends in the middle of a character"};
    unsigned long code = unit(i);
    if (code >= 0xD800 && code <= 0xDBFF && i + 3 < bytes.size() && unit(i + 2) >= 0xDC00 && unit(i + 2) <= 0xDFFF) {
      code = 0x10000 + ((code - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
      i += 2;
    } else if (code >= 0xD800 && code <= 0xDFFF) {
      return Error{source, line, "a UTF-16 surrogate without its pair"};
    }
    if (code == '\n') ++line;
    append_utf8(code, out);
  }
  return out;
}

class Parser {
 public:
  Parser(const std::string& xml, const std::string& source) : xml_(xml), source_(source) {}

  Result<XmlElement> document() {
    auto skipped = skip_misc();
    if (!skipped.ok()) return skipped.error();
    if (pos_ >= xml_.size() || xml_[pos_] != '<') return fail("no root element");
    XmlElement root;
    auto got = element(root, 0);
    if (!got.ok()) return got.error();
    skipped = skip_misc();
    if (!skipped.ok()) return skipped.error();
    if (pos_ < xml_.size()) return fail("content after the root element </" + root.name + ">");
    return root;
  }

 private:
  Error fail(const std::string& message) const { return Error{source_, line_, message}; }

  void advance(size_t n) {
    for (size_t i = 0; i < n && pos_ < xml_.size(); ++i, ++pos_)
      if (xml_[pos_] == '\n') ++line_;
  }
  bool starts(const char* s) const { return xml_.compare(pos_, std::strlen(s), s) == 0; }

  /// Moves past `end`; false when the document ends first.
  bool skip_past(const char* end) {
    const size_t at = xml_.find(end, pos_);
    if (at == std::string::npos) return false;
    advance(at + std::strlen(end) - pos_);
    return true;
  }

  /// Spaces, comments, processing instructions and a DOCTYPE between elements.
  Result<bool> skip_misc() {
    for (;;) {
      while (pos_ < xml_.size() && is_space(xml_[pos_])) advance(1);
      if (starts("<!--")) {
        if (!skip_past("-->")) return fail("a comment is not closed");
      } else if (starts("<?")) {
        if (!skip_past("?>")) return fail("a processing instruction is not closed");
      } else if (starts("<!DOCTYPE")) {
        if (!skip_doctype()) return fail("the DOCTYPE is not closed");
      } else {
        return true;
      }
    }
  }

  /// Moves past a DOCTYPE and its internal subset ([...], whose declarations, comments and
  /// quoted literals may hold '>'); its declarations are not used, as ViSP's parser skips them.
  bool skip_doctype() {
    bool in_subset = false;
    advance(9);
    while (pos_ < xml_.size()) {
      const char c = xml_[pos_];
      if (c == '"' || c == '\'') {
        advance(1);
        if (!skip_past(c == '"' ? "\"" : "'")) return false;
      } else if (in_subset && starts("<!--")) {
        if (!skip_past("-->")) return false;
      } else if (c == '[' && !in_subset) {
        in_subset = true;
        advance(1);
      } else if (c == ']' && in_subset) {
        in_subset = false;
        advance(1);
      } else if (c == '>' && !in_subset) {
        advance(1);
        return true;
      } else {
        advance(1);
      }
    }
    return false;
  }

  std::string name() {
    const size_t begin = pos_;
    while (pos_ < xml_.size() && !is_space(xml_[pos_]) && xml_[pos_] != '>' && xml_[pos_] != '/' &&
           xml_[pos_] != '<' && xml_[pos_] != '=')
      advance(1);
    return xml_.substr(begin, pos_ - begin);
  }

  /// Appends character data up to the next '<', decoding the five predefined entities.
  Result<bool> text(std::string& out) {
    static const char* const kEntities[][2] = {{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}, {"&quot;", "\""},
                                               {"&apos;", "'"}};
    while (pos_ < xml_.size() && xml_[pos_] != '<') {
      if (xml_[pos_] != '&') {
        out += xml_[pos_];
        advance(1);
        continue;
      }
      if (starts("&#")) {
        auto referenced = character_reference(out);
        if (!referenced.ok()) return referenced.error();
        continue;
      }
      bool known = false;
      for (const auto& entity : kEntities)
        if (starts(entity[0])) {
          out += entity[1];
          advance(std::strlen(entity[0]));
          known = true;
          break;
        }
      if (!known) return fail("an unknown entity (only &lt; &gt; &amp; &quot; &apos; and &#N; &#xN; are read)");
    }
    return true;
  }

  /// "&#53;" or "&#x35;": appends the character it names, in UTF-8.
  Result<bool> character_reference(std::string& out) {
    const bool hex = xml_.compare(pos_, 3, "&#x") == 0;
    size_t at = pos_ + (hex ? 3 : 2);
    unsigned long code = 0;
    const size_t digits_start = at;
    for (; at < xml_.size() && at - digits_start < 8; ++at) {
      const char c = xml_[at];
      int digit = -1;
      if (c >= '0' && c <= '9') digit = c - '0';
      else if (hex && c >= 'a' && c <= 'f') digit = c - 'a' + 10;
      else if (hex && c >= 'A' && c <= 'F') digit = c - 'A' + 10;
      if (digit < 0) break;
      code = code * (hex ? 16 : 10) + static_cast<unsigned long>(digit);
    }
    if (at == digits_start || at >= xml_.size() || xml_[at] != ';' || !is_xml_char(code))
      return fail("a malformed character reference (&#N; or &#xN; naming a character XML allows)");
    append_utf8(code, out);
    advance(at + 1 - pos_);
    return true;
  }

  /// The start tag's name and attributes (read past); true when the tag closes itself.
  Result<bool> start_tag(XmlElement& out) {
    advance(1);  // '<'
    out.line = line_;
    out.name = name();
    if (out.name.empty()) return fail("a tag without a name");
    for (;;) {
      while (pos_ < xml_.size() && is_space(xml_[pos_])) advance(1);
      if (pos_ >= xml_.size()) return fail("<" + out.name + "> is not closed");
      if (starts("/>")) {
        advance(2);
        return true;
      }
      if (xml_[pos_] == '>') {
        advance(1);
        return false;
      }
      const std::string attribute = name();
      while (pos_ < xml_.size() && is_space(xml_[pos_])) advance(1);
      if (attribute.empty() || pos_ >= xml_.size() || xml_[pos_] != '=') return fail("a malformed attribute in <" + out.name + ">");
      advance(1);
      while (pos_ < xml_.size() && is_space(xml_[pos_])) advance(1);
      const char quote = pos_ < xml_.size() ? xml_[pos_] : '\0';
      if (quote != '"' && quote != '\'') return fail("an unquoted attribute value in <" + out.name + ">");
      advance(1);
      if (!skip_past(quote == '"' ? "\"" : "'")) return fail("an attribute value in <" + out.name + "> is not closed");
    }
  }

  Result<bool> element(XmlElement& out, int depth) {
    if (depth > 64) return fail("elements nested deeper than 64 levels");
    auto self_closed = start_tag(out);
    if (!self_closed.ok()) return self_closed.error();
    if (self_closed.value()) return true;
    std::string content;
    for (;;) {
      auto got = text(content);
      if (!got.ok()) return got.error();
      if (pos_ >= xml_.size()) return Error{source_, out.line, "<" + out.name + "> is not closed"};
      if (starts("<!--")) {
        if (!skip_past("-->")) return fail("a comment is not closed");
      } else if (starts("<![CDATA[")) {
        const size_t begin = pos_ + 9, end = xml_.find("]]>", begin);
        if (end == std::string::npos) return fail("a CDATA section is not closed");
        content += xml_.substr(begin, end - begin);
        advance(end + 3 - pos_);
      } else if (starts("<?")) {
        if (!skip_past("?>")) return fail("a processing instruction is not closed");
      } else if (starts("</")) {
        advance(2);
        const std::string closing = name();
        while (pos_ < xml_.size() && is_space(xml_[pos_])) advance(1);
        if (closing != out.name || pos_ >= xml_.size() || xml_[pos_] != '>')
          return fail("</" + closing + "> does not close <" + out.name + "> (line " + std::to_string(out.line) + ")");
        advance(1);
        out.text = trimmed(content);
        return true;
      } else {
        out.children.emplace_back();
        auto child = element(out.children.back(), depth + 1);
        if (!child.ok()) return child.error();
      }
    }
  }

  const std::string& xml_;
  const std::string& source_;
  size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

Result<XmlElement> parse_xml(const std::string& xml, const std::string& source) {
  const Result<std::string> utf8 = as_utf8(xml, source);
  if (!utf8.ok()) return utf8.error();
  return Parser(utf8.value(), source).document();
}

Result<XmlElement> read_xml_file(const std::string& path) {
  auto text = read_input_text(path);
  if (!text.ok()) return text.error();
  return parse_xml(text.value(), path);
}

}  // namespace edgetrack
