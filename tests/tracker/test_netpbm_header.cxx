// SPDX-License-Identifier: BSD-3-Clause
/// The portable netpbm header parser (netpbm_header.h) that the app and the firmware share: what
/// it reads, where the samples start, and the line each bad header is reported on.
#include <cstring>
#include <string>

#include "edgetrack/netpbm_header.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

NetpbmHeader parse(const std::string& text) {
  size_t next = 0;
  return parse_netpbm_header([&]() -> int {
    return next < text.size() ? static_cast<unsigned char>(text[next++]) : -1;
  });
}

bool says(const NetpbmHeader& h, const char* words) { return h.problem && std::strstr(h.problem, words) != nullptr; }

}  // namespace

static void test_netpbm_header() {
  const std::string binary = "P5\n# a comment\n320 240\n255\n";
  const NetpbmHeader grey = parse(binary + "\x01\x02");
  TEST("a binary PGM with a comment parses", grey.ok(), true);
  TEST("its size and maxval", grey.width == 320 && grey.height == 240 && grey.maxval == 255, true);
  TEST("grey and binary", !grey.colour && !grey.ascii, true);
  TEST_EQUAL("the samples start after the one white space ending the header", grey.samples_at, binary.size());
  TEST_EQUAL("on the line after the header's", grey.samples_line, 5);
  TEST_EQUAL("its size is on line 3", grey.size_line, 3);

  const NetpbmHeader colour = parse("P3 2#width\n1 15 0 1 2 3 4 5");
  TEST("an ASCII PPM, a comment right after a number", colour.ok() && colour.colour && colour.ascii, true);
  TEST("its numbers", colour.width == 2 && colour.height == 1 && colour.maxval == 15, true);
  TEST_EQUAL("its samples start on its second line", colour.samples_line, 2);

  const NetpbmHeader text = parse("hello");
  TEST("a file without a signature is refused", says(text, "no P2, P3, P5 or P6 signature"), true);
  TEST_EQUAL("on line 1", text.line, 1);
  TEST("an empty file is refused", says(parse(""), "signature"), true);
  const NetpbmHeader missing = parse("P5\n320\n\n");
  TEST("a header that ends early is malformed", says(missing, "malformed"), true);
  TEST_EQUAL("at its end, line 3", missing.line, 3);
  const NetpbmHeader letters = parse("P5\n# size\n32O 240\n255\n");
  TEST("a letter in a number is malformed", says(letters, "malformed"), true);
  TEST_EQUAL("on the number's line", letters.line, 3);
  TEST("a header number over a million is refused", says(parse("P5 3000000 1 255\n"), "malformed"), true);
  TEST("maxval ended by no white space is malformed", says(parse("P5 2 2 255"), "malformed"), true);
  const NetpbmHeader zero = parse("P2\n2 2\n0\n");
  TEST("maxval 0 is refused", says(zero, "maxval is outside 1..65535"), true);
  TEST_EQUAL("on its line", zero.line, 3);
  TEST("maxval 65536 is refused", says(parse("P5 1 1 65536\n"), "maxval"), true);
  TEST("maxval 65535 is taken", parse("P5 1 1 65535\n").ok(), true);

  // The samples of an ASCII file, with the same number rules.
  const std::string samples = "7 # seven\n 300\nx";
  size_t next = 0;
  NetpbmNumbers numbers([&]() -> int { return next < samples.size() ? samples[next++] : -1; });
  int a = 0, b = 0, c = 0;
  TEST("ASCII samples read past comments and white space", numbers.number(a) && numbers.number(b) && a == 7 && b == 300,
       true);
  TEST("a sample that is not a number is refused", numbers.number(c), false);
  TEST_EQUAL("on its line", numbers.line(), 3);
}

TESTMAIN(test_netpbm_header)
