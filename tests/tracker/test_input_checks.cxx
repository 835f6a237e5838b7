// SPDX-License-Identifier: BSD-3-Clause
/// The portable input checks refuse what they must, with the file, the line and the field: a
/// directory, a device or an oversized file before reading it; numbers that are not numbers,
/// not finite, out of their field's range, or fractional where a whole number counts.
#include <cstdio>
#include <string>

#include "edgetrack/input_file.h"
#include "edgetrack/number_text.h"
#include "edgetrack/pose_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

static std::string temp_file(const char* name, const std::string& text) {
  const std::string path = std::string(EDGETRACK_TEST_OUTPUT) + "/" + name;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file) {
    std::fwrite(text.data(), 1, text.size(), file);
    std::fclose(file);
  }
  return path;
}

static bool says(const Error& error, const std::string& text) { return error.text().find(text) != std::string::npos; }

static void test_input_checks() {
  const std::string ok = temp_file("input_ok.txt", "1 2\n# comment\n3\n");
  auto text = read_input_text(ok);
  TEST("a small regular file is read whole", text.ok() && text.value() == "1 2\n# comment\n3\n", true);
  auto too_big = read_input_text(ok, 4);
  TEST("a file over its cap is refused before reading", too_big.ok(), false);
  TEST("saying how large it is", says(too_big.error(), "is 16 bytes, more than the 4"), true);
  auto directory = read_input_text(EDGETRACK_TEST_OUTPUT);
  TEST("a directory is refused", !directory.ok() && says(directory.error(), "is a directory"), true);
  auto device = read_input_text("/dev/zero");
  TEST("a device is refused without reading it", !device.ok() && says(device.error(), "not a regular file"), true);
  auto missing = read_input_text(std::string(EDGETRACK_TEST_OUTPUT) + "/no_such_file");
  TEST("a missing file is named", !missing.ok() && says(missing.error(), "no_such_file: no such file"), true);

  auto words = read_words(ok);
  TEST("words skip comments", words.ok() && words.value().size() == 3, true);
  TEST("and keep their lines", words.ok() && words.value()[2].line == 3, true);

  const FieldRange range{"tz (m)", -1000, 1000};
  TEST("a number inside its range is read", parse_field("0.25", range, "f", 2).ok(), true);
  for (const char* bad : {"nan", "inf", "-inf", "1e400"}) {
    auto refused = parse_field(bad, range, "f", 2);
    TEST("a non-finite number is refused", !refused.ok() && says(refused.error(), "f:2: tz (m) is not a finite number"),
         true);
  }
  auto far = parse_field("1e308", range, "f", 2);
  TEST("a finite number out of range is refused with the range", !far.ok() && says(far.error(), "out of its range (-1000..1000)"),
       true);
  TEST("text after a number is refused", parse_field("1.5x", range, "f", 2).ok(), false);
  const FieldRange count{"the number of points", 1, 10000};
  TEST("a whole number is read", parse_whole_field("4", count, "f", 1).ok() && parse_whole_field("4", count, "f", 1).value() == 4,
       true);
  TEST("a fraction is not a whole number", parse_whole_field("4.5", count, "f", 1).ok(), false);
  TEST("an overflowing count is out of range", parse_whole_field("99999999999999999999999", count, "f", 1).ok(), false);

  const std::string nan_pos = temp_file("nan.pos", "0.01\n0\n0.6\nnan\n0\n0\n");
  auto pose = read_pos(nan_pos);
  TEST("a .pos with a NaN rotation is refused at its line", !pose.ok() && says(pose.error(), "nan.pos:4: tux (rad)"), true);
  const std::string short_pos = temp_file("short.pos", "0 0 0.5\n");
  TEST("a .pos with 3 numbers is refused", read_pos(short_pos).ok(), false);
  const std::string good_pos = temp_file("good.pos", "0.01 -0.02 0.5 0.1 0 0\n");
  TEST("a good .pos is read", read_pos(good_pos).ok(), true);
}

TESTMAIN(test_input_checks)
