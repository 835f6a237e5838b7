// SPDX-License-Identifier: BSD-3-Clause
/// The little XML that configuration files use: nested elements with text, comments, a
/// declaration and attributes (read past), each element with the line it starts on.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/result.h"

namespace edgetrack {

struct XmlElement {
  std::string name;
  std::string text;  ///< the element's own character data, entities decoded, spaces trimmed
  int line = 0;      ///< 1-based line of its start tag
  std::vector<XmlElement> children;
};

/// Parses `xml` into its root element: UTF-8 (a byte-order mark dropped) or UTF-16 (little or
/// big endian), the predefined entities and character references (&#53; &#x35;) decoded, a
/// DOCTYPE and its internal subset skipped. A malformed document (an unclosed or mismatched tag, a
/// second root, text outside the root) is an Error naming `source` and the line.
Result<XmlElement> parse_xml(const std::string& xml, const std::string& source);

/// Reads (read_input_text: a device or an oversized file is refused by name) and parses the file at `path`.
Result<XmlElement> read_xml_file(const std::string& path);

}  // namespace edgetrack
