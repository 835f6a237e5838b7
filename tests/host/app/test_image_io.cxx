// SPDX-License-Identifier: BSD-3-Clause
// Our PGM/PPM and raw RGB565 readers read what the writers wrote, scale other maxvals to 8 bits,
// and refuse broken files with a message naming the file.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

#include "image_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack_app;

static std::string temp_path(const char* name) { return std::string(APP_TEST_TMP) + "/" + name; }

static void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

static void test_image_io() {
  RgbImage image = make_image(5, 3);
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<uint8_t>(i * 17);
  const std::string ppm = temp_path("roundtrip.ppm");
  TEST("a PPM is written", write_ppm(ppm, image).ok(), true);
  auto back = read_netpbm(ppm);
  TEST("the written PPM reads back", back.ok(), true);
  TEST("the PPM round trip keeps every byte", back.ok() && back.value().rgb == image.rgb, true);

  write_text(temp_path("ascii.pgm"), "P2\n# a comment\n2 2\n15\n0 15\n5 10\n");
  auto grey = read_netpbm(temp_path("ascii.pgm"));
  TEST("an ASCII PGM with a comment reads", grey.ok(), true);
  if (grey.ok()) {
    TEST_EQUAL("maxval 15 scales 15 to 255", int(grey.value().pixel(1, 0)[0]), 255);
    TEST_EQUAL("maxval 15 scales 5 to 85", int(grey.value().pixel(0, 1)[1]), 85);
    TEST_EQUAL("grey goes to all three channels", int(grey.value().pixel(1, 1)[2]), 170);
  }

  write_text(temp_path("binary.pgm"), "P5\n# c\n3 2\n255\nABCDEF");
  auto binary = read_netpbm_pixels(temp_path("binary.pgm"));
  TEST("an 8-bit binary PGM reads", binary.ok(), true);
  if (binary.ok()) {
    const edgetrack::FrameView view = binary.value().view();
    TEST("it goes to the tracker as grey8, 3 bytes a row", view.layout == edgetrack::PixelLayout::kGrey8 && view.row_bytes == 3,
         true);
    TEST("its pixels are the file's bytes after the header, not a copy",
         view.pixels == binary.value().bytes.data() + 15 && view.row(1)[2] == 'F', true);
  }
  RgbImage colour = make_image(2, 1);
  colour.rgb = {1, 2, 3, 4, 5, 6};
  write_ppm(temp_path("colour.ppm"), colour);
  auto rgb = read_netpbm_pixels(temp_path("colour.ppm"));
  TEST("an 8-bit binary PPM goes to the tracker as RGB24 read in place",
       rgb.ok() && rgb.value().layout == edgetrack::PixelLayout::kRgb24 && rgb.value().offset > 0 &&
           rgb.value().view().row(0)[5] == 6,
       true);

  TEST("a PGM is written", write_pgm(temp_path("grey.pgm"), colour).ok(), true);
  auto grey_back = read_netpbm_pixels(temp_path("grey.pgm"));
  TEST("the written PGM holds the luma of each pixel (vpImageConvert's rule: 2 and 5)",
       grey_back.ok() && grey_back.value().layout == edgetrack::PixelLayout::kGrey8 &&
           grey_back.value().view().row(0)[0] == 2 && grey_back.value().view().row(0)[1] == 5,
       true);

  write_text(temp_path("short.pgm"), std::string("P5\n4 4\n255\n") + std::string(10, 'x'));
  auto truncated = read_netpbm(temp_path("short.pgm"));
  TEST("a truncated PGM is refused", truncated.ok(), false);
  TEST("the message names the file", truncated.error().text().find("short.pgm") != std::string::npos, true);
  write_text(temp_path("text.pgm"), "hello");
  TEST("a file without a netpbm signature is refused", read_netpbm(temp_path("text.pgm")).ok(), false);

  std::vector<uint16_t> packed;
  to_rgb565(image, packed);
  TEST("raw RGB565 is written", write_raw_rgb565(temp_path("frame.rgb565"), packed).ok(), true);
  auto raw = read_raw_rgb565(temp_path("frame.rgb565"), 5, 3);
  TEST("raw RGB565 reads back", raw.ok(), true);
  TEST("raw RGB565 equals the bit-replicated packing",
       raw.ok() && to_rgb_image(raw.value().view()).rgb == from_rgb565(packed, 5, 3).rgb, true);
  TEST("raw RGB565 goes to the tracker as it was read: RGB565 from the file's first byte",
       raw.ok() && raw.value().layout == edgetrack::PixelLayout::kRgb565 && raw.value().offset == 0 &&
           raw.value().view().row_bytes == 10 &&
           std::equal(packed.begin(), packed.end(), reinterpret_cast<const uint16_t*>(raw.value().view().pixels)),
       true);
  auto wrong = read_raw_rgb565(temp_path("frame.rgb565"), 6, 3);
  TEST("raw RGB565 of the wrong size is refused", wrong.ok(), false);
  TEST("the size message gives the byte counts", wrong.error().message.find("30 bytes, 36 expected") != std::string::npos,
       true);
  const RgbImage white = from_rgb565({0xffff}, 1, 1);
  TEST_EQUAL("RGB565 white expands to 255", int(white.rgb[0]) + int(white.rgb[1]) + int(white.rgb[2]), 765);

  RgbImage big = make_image(4, 2);
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 2; ++y) big.pixel(x, y)[0] = static_cast<uint8_t>(x < 2 ? 10 * (x + y) : 100);
  const RgbImage half = downscale(big, 2);
  TEST_EQUAL("downscale halves the width", half.width, 2);
  TEST_EQUAL("downscale averages a block (0, 10, 10, 20 -> 10)", int(half.pixel(0, 0)[0]), 10);
  TEST_EQUAL("downscale keeps a flat block", int(half.pixel(1, 0)[0]), 100);

  // 16-bit samples scale through the table exactly as round(255 v / maxval).
  const int maxval = 1000;
  std::string sixteen = "P5\n3 1\n1000\n";
  for (int v : {0, 501, 1000}) sixteen += std::string{static_cast<char>(v >> 8), static_cast<char>(v & 0xff)};
  write_text(temp_path("sixteen.pgm"), sixteen);
  auto deep = read_netpbm(temp_path("sixteen.pgm"));
  TEST("a 16-bit PGM reads", deep.ok(), true);
  if (deep.ok()) {
    TEST_EQUAL("maxval 1000 scales 501 to round(255 * 501 / 1000) = 128", int(deep.value().pixel(1, 0)[0]),
               (501 * 255 + maxval / 2) / maxval);
    TEST_EQUAL("and 1000 to 255", int(deep.value().pixel(2, 0)[0]), 255);
  }
  write_text(temp_path("wide.pgm"), "P5\n16385 1\n255\n");
  auto wide = read_netpbm(temp_path("wide.pgm"));
  TEST("a side over 16384 is refused before allocating", wide.ok(), false);
  TEST("naming the size", wide.error().message.find("16385x1 is outside") != std::string::npos, true);
  TEST("usable_image_size takes 16384 x 4096", usable_image_size(16384, 4096), true);
  TEST("but not 16384 x 4097 (over 64 M pixels)", usable_image_size(16384, 4097), false);
  TEST("nor a zero side", usable_image_size(0, 10), false);
  auto directory = read_netpbm(APP_TEST_TMP);
  TEST("a directory is not read as an image", directory.ok(), false);
  TEST("and says so", directory.error().message.find("is a directory") != std::string::npos, true);
}

TESTMAIN(test_image_io)
