// SPDX-License-Identifier: BSD-3-Clause
// Frame sources: printf patterns (starting at 0 or 1), directories in name order, --first and
// --last, and an empty sequence refused with the pattern in the message.
#include <filesystem>

#include "frame_source.h"
#include "testlib/testlib_test.h"

using namespace edgetrack_app;

static void test_frame_source() {
  TEST("%04d expands", expand_pattern("seq/frame%04d.pgm", 7), std::string("seq/frame0007.pgm"));
  TEST("%d expands", expand_pattern("f%d.ppm", 12), std::string("f12.ppm"));
  TEST("a name without a conversion stays", expand_pattern("one.pgm", 3), std::string("one.pgm"));

  const std::string dir = std::string(APP_TEST_TMP) + "/seq";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  RgbImage image = make_image(4, 3);
  for (int k = 1; k <= 3; ++k) {
    image.rgb[0] = static_cast<uint8_t>(k);
    write_ppm(expand_pattern(dir + "/f%03d.ppm", k), image);
  }
  SourceOptions options;
  options.images = dir + "/f%03d.ppm";
  auto source = open_frame_source(options);
  TEST("a pattern starting at 1 opens", source.ok(), true);
  if (source.ok()) {
    Frame frame;
    int count = 0, first_index = -1;
    while (source.value()->next(frame).value()) {
      if (count == 0) first_index = frame.index;
      ++count;
    }
    TEST_EQUAL("it starts at frame 1", first_index, 1);
    TEST_EQUAL("it reads the three frames", count, 3);
  }
  options.images = dir;
  options.first = 1;
  options.last = 1;
  auto listed = open_frame_source(options);
  TEST("a directory opens", listed.ok(), true);
  if (listed.ok()) {
    Frame frame;
    TEST("--first 1 --last 1 of a directory gives one frame", listed.value()->next(frame).value(), true);
    TEST_EQUAL("the frame numbered 1 in its name (f001.ppm)", int(frame.pixels.view().row(0)[0]), 1);
    TEST_EQUAL("its index is the number in its name", frame.index, 1);
    TEST("and then ends", listed.value()->next(frame).value(), false);
  }
  // Names without a number at their end: frames are numbered by their place in name order.
  const std::string plain = std::string(APP_TEST_TMP) + "/plain_names";
  std::filesystem::create_directories(plain);
  for (const char* stem : {"alpha", "beta", "gamma"}) {
    RgbImage image = make_image(2, 2);
    image.rgb[0] = static_cast<uint8_t>(stem[0]);
    write_ppm(plain + "/" + stem + ".ppm", image);
  }
  options = SourceOptions{};
  options.images = plain;
  options.first = 1;
  auto positional = open_frame_source(options);
  TEST("a directory of unnumbered names opens", positional.ok(), true);
  if (positional.ok()) {
    Frame frame;
    TEST("--first 1 gives a frame", positional.value()->next(frame).value(), true);
    TEST_EQUAL("the second name in order (beta)", int(frame.pixels.view().row(0)[0]), int('b'));
    TEST_EQUAL("numbered by its place", frame.index, 1);
  }
  options = SourceOptions{};
  options.images = dir;
  options.first = 3;
  options.last = 2;
  auto reversed = open_frame_source(options);
  TEST("first after last is refused", reversed.ok(), false);
  TEST("saying so", reversed.error().text().find("--first 3 is after --last 2") != std::string::npos, true);
  options = SourceOptions{};
  options.images = dir + "/none%03d.ppm";
  auto empty = open_frame_source(options);
  TEST("an empty sequence is refused", empty.ok(), false);
  TEST("with the pattern and the problem", empty.error().text().find("none%03d.ppm: empty sequence") != std::string::npos,
       true);
}

TESTMAIN(test_frame_source)
