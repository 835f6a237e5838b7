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
        if (!skip_past(">")) return fail("the DOCTYPE is not closed");
      } else {
        return true;
      }
    }
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
      bool known = false;
      for (const auto& entity : kEntities)
        if (starts(entity[0])) {
          out += entity[1];
          advance(std::strlen(entity[0]));
          known = true;
          break;
        }
      if (!known) return fail("an unknown entity (only &lt; &gt; &amp; &quot; &apos; are read)");
    }
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
  return Parser(xml, source).document();
}

Result<XmlElement> read_xml_file(const std::string& path) {
  auto text = read_input_text(path);
  if (!text.ok()) return text.error();
  return parse_xml(text.value(), path);
}

}  // namespace edgetrack
