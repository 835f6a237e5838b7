// SPDX-License-Identifier: BSD-3-Clause
/// Valid XML that ViSP's parser reads is read the same: a UTF-8 byte-order mark, UTF-16 of either
/// byte order, character references and the predefined entities, a DOCTYPE with an internal
/// subset; and what is not XML (a lone surrogate, a reference to no character) is refused at its
/// line.
#include <string>

#include "edgetrack/xml_document.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

const char* kCamera = "<?xml version=\"1.0\"?>\n<conf>\n<px>547.5</px>\n</conf>\n";

/// The camera document's <px>, or "" when it does not parse.
std::string px_of(const std::string& bytes) {
  const Result<XmlElement> root = parse_xml(bytes, "doc.xml");
  if (!root.ok() || root.value().children.empty()) return "";
  return root.value().children[0].text;
}

std::string utf16(const std::string& ascii, bool little, bool mark) {
  std::string out;
  if (mark) out += little ? "\xFF\xFE" : "\xFE\xFF";
  for (char c : ascii) {
    out += little ? std::string(1, c) + '\0' : std::string(1, '\0') + c;
  }
  return out;
}

void encodings() {
  TEST_EQUAL("UTF-8 without a mark", px_of(kCamera), std::string("547.5"));
  TEST_EQUAL("UTF-8 with its byte-order mark", px_of("\xEF\xBB\xBF" + std::string(kCamera)), std::string("547.5"));
  TEST_EQUAL("UTF-16 little endian with its mark", px_of(utf16(kCamera, true, true)), std::string("547.5"));
  TEST_EQUAL("UTF-16 big endian with its mark", px_of(utf16(kCamera, false, true)), std::string("547.5"));
  TEST_EQUAL("UTF-16 little endian without a mark", px_of(utf16(kCamera, true, false)), std::string("547.5"));
  // U+00E9 (one unit) and U+1F600 (a surrogate pair) come out as UTF-8.
  const std::string accented =
      utf16("<a>", true, true) + std::string("\xE9\x00\x3D\xD8\x00\xDE", 6) + utf16("</a>", true, false);
  const Result<XmlElement> a = parse_xml(accented, "a.xml");
  TEST("UTF-16 beyond ASCII becomes UTF-8", a.ok() && a.value().text == "\xC3\xA9\xF0\x9F\x98\x80", true);
  const std::string lone = utf16("<a>\n", true, true) + "\x3D\xD8" + utf16("</a>", true, false);
  const Result<XmlElement> broken = parse_xml(lone, "lone.xml");
  TEST("a lone surrogate is refused at its line", !broken.ok() && broken.error().line == 2, true);
  const Result<XmlElement> odd = parse_xml(utf16("<a/>", true, true) + "x", "odd.xml");
  TEST("UTF-16 of an odd number of bytes is refused", !odd.ok() && odd.error().file == "odd.xml", true);
}

void references() {
  TEST_EQUAL("&#X35; (a capital X) is not a reference", px_of("<conf><px>&#X35;</px></conf>"), std::string(""));
  TEST_EQUAL("&#53; and &#x37; are '5' and '7'", px_of("<conf><px>&#53;4&#x37;.5</px></conf>"), std::string("547.5"));
  TEST_EQUAL("the predefined entities", px_of("<conf><px>&lt;&gt;&amp;&quot;&apos;</px></conf>"), std::string("<>&\"'"));
  const Result<XmlElement> e = parse_xml("<a>&#xE9;&#128512;</a>", "e.xml");
  TEST("a reference beyond ASCII is UTF-8", e.ok() && e.value().text == "\xC3\xA9\xF0\x9F\x98\x80", true);
  for (const char* bad : {"<a>\n&#0;</a>", "<a>\n&#xD800;</a>", "<a>\n&#x110000;</a>", "<a>\n&#12</a>", "<a>\n&#;</a>",
                          "<a>\n&unknown;</a>"}) {
    const Result<XmlElement> r = parse_xml(bad, "bad.xml");
    TEST((std::string("refused at its line: ") + bad).c_str(), !r.ok() && r.error().line == 2, true);
  }
}

void doctype() {
  const char* with_subset =
      "<?xml version=\"1.0\"?>\n"
      "<!DOCTYPE conf [\n"
      "  <!ELEMENT conf (px)>\n"
      "  <!-- a comment with > and ] in it -->\n"
      "  <!ENTITY arrow \"->\">\n"
      "  <!ATTLIST conf note CDATA '>]'>\n"
      "]>\n"
      "<conf>\n<px>547.5</px>\n</conf>\n";
  TEST_EQUAL("an internal DTD subset is skipped", px_of(with_subset), std::string("547.5"));
  const Result<XmlElement> root = parse_xml(with_subset, "doc.xml");
  TEST_EQUAL("lines are counted through it", root.ok() ? root.value().children[0].line : 0, 9);
  TEST_EQUAL("a DOCTYPE naming an external DTD", px_of("<!DOCTYPE conf SYSTEM \"conf>.dtd\"><conf><px>1</px></conf>"),
             std::string("1"));
  const Result<XmlElement> open = parse_xml("<!DOCTYPE conf [\n<!ELEMENT conf ANY>\n<conf/>", "open.xml");
  TEST("an unclosed subset is refused", !open.ok() && open.error().message.find("DOCTYPE") != std::string::npos, true);
}

}  // namespace

static void test_xml_document() {
  encodings();
  references();
  doctype();
}

TESTMAIN(test_xml_document)
