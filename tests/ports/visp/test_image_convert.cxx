// SPDX-License-Identifier: BSD-3-Clause
/// vpImageConvert: the documented integer rounding rule for RGB24, RGBa and RGB565 to grey,
/// and the strided RGB565 rows the tracker's grey step converts a box of a frame with.
#include <cmath>
#include <cstdint>
#include <vector>

#include "testlib/testlib_test.h"
#include "visp3/core/vpImage.h"
#include "visp3/core/vpImageConvert.h"
#include "visp3/core/vpRGBa.h"

namespace {

uint32_t next_random(uint32_t& state) {
  state = state * 1664525u + 1013904223u;
  return state >> 8;
}

/// The rule from the header, written out independently: round to nearest of the weighted sum.
unsigned int expected_grey(unsigned int r, unsigned int g, unsigned int b) {
  const unsigned int sum = 13933u * r + 46871u * g + 4732u * b;
  return sum / 65536u + (sum % 65536u >= 32768u ? 1u : 0u);
}

void test_rule() {
  bool grey_fixed = true;
  for (unsigned int v = 0; v < 256; ++v) grey_fixed = grey_fixed && vpImageConvert::rgbToGrey(v, v, v) == v;
  TEST("grey pixels (r = g = b) convert to themselves, all 256 levels", grey_fixed, true);

  bool exact = true, near_bt709 = true;
  for (unsigned int r = 0; r < 256; r += 5) {
    for (unsigned int g = 0; g < 256; g += 3) {
      for (unsigned int b = 0; b < 256; b += 7) {
        const unsigned int got = vpImageConvert::rgbToGrey(r, g, b);
        exact = exact && got == expected_grey(r, g, b);
        const double luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        near_bt709 = near_bt709 && std::fabs(got - luma) <= 0.5 + 0.01;
      }
    }
  }
  TEST("rgbToGrey is (13933 R + 46871 G + 4732 B + 32768) >> 16", exact, true);
  TEST("rgbToGrey is within half a level (+0.01) of BT.709 luma", near_bt709, true);
  TEST_EQUAL("pure red gives 54", static_cast<int>(vpImageConvert::rgbToGrey(255, 0, 0)), 54);
  TEST_EQUAL("pure green gives 182", static_cast<int>(vpImageConvert::rgbToGrey(0, 255, 0)), 182);
  TEST_EQUAL("pure blue gives 18", static_cast<int>(vpImageConvert::rgbToGrey(0, 0, 255)), 18);
}

void test_rgb565() {
  TEST_EQUAL("RGB565 white is 255", static_cast<int>(vpImageConvert::rgb565ToGrey(0xFFFF)), 255);
  TEST_EQUAL("RGB565 black is 0", static_cast<int>(vpImageConvert::rgb565ToGrey(0x0000)), 0);
  TEST_EQUAL("RGB565 full red is grey of (255, 0, 0)", static_cast<int>(vpImageConvert::rgb565ToGrey(0xF800)), 54);
  TEST_EQUAL("RGB565 full green is grey of (0, 255, 0)", static_cast<int>(vpImageConvert::rgb565ToGrey(0x07E0)), 182);
  TEST_EQUAL("RGB565 full blue is grey of (0, 0, 255)", static_cast<int>(vpImageConvert::rgb565ToGrey(0x001F)), 18);

  // Every 16-bit value: bit-replicated channels, then the rule; the array form agrees pixel by pixel.
  std::vector<uint16_t> all(65536);
  for (unsigned int p = 0; p < 65536; ++p) all[p] = static_cast<uint16_t>(p);
  std::vector<unsigned char> grey(65536);
  vpImageConvert::RGB565ToGrey(all.data(), grey.data(), 65536);
  bool exact = true;
  for (unsigned int p = 0; p < 65536; ++p) {
    const unsigned int r5 = p >> 11, g6 = (p >> 5) & 63u, b5 = p & 31u;
    const unsigned int r = r5 * 255u / 31u, g = g6 * 255u / 63u, b = b5 * 255u / 31u;
    // Bit replication equals round(c * 255 / max) for 5 and 6 bits except where it is one above the
    // floor; accept only the replicated value itself.
    const unsigned int rr = (r5 << 3) | (r5 >> 2), gg = (g6 << 2) | (g6 >> 4), bb = (b5 << 3) | (b5 >> 2);
    exact = exact && grey[p] == expected_grey(rr, gg, bb) && rr >= r && gg >= g && bb >= b && rr <= r + 1 &&
            gg <= g + 1 && bb <= b + 1;
  }
  TEST("all 65536 RGB565 values follow the rule on bit-replicated channels", exact, true);
}

void test_rgb24_rgba() {
  uint32_t seed = 12345;
  const unsigned int n = 1000;
  std::vector<unsigned char> rgb(3 * n), rgba(4 * n), grey24(n), grey32(n);
  vpImage<vpRGBa> colour(25, 40);
  for (unsigned int k = 0; k < n; ++k) {
    const uint32_t x = next_random(seed);
    const unsigned char r = x & 0xFF, g = (x >> 8) & 0xFF, b = (x >> 16) & 0xFF;
    rgb[3 * k] = r, rgb[3 * k + 1] = g, rgb[3 * k + 2] = b;
    rgba[4 * k] = r, rgba[4 * k + 1] = g, rgba[4 * k + 2] = b, rgba[4 * k + 3] = static_cast<unsigned char>(k);
    colour.bitmap[k] = vpRGBa(r, g, b, static_cast<unsigned char>(k));
  }
  vpImageConvert::RGBToGrey(rgb.data(), grey24.data(), n);
  vpImageConvert::RGBaToGrey(rgba.data(), grey32.data(), n);
  vpImage<unsigned char> grey_image;
  vpImageConvert::convert(colour, grey_image);
  bool same = grey_image.getHeight() == 25 && grey_image.getWidth() == 40;
  for (unsigned int k = 0; k < n && same; ++k) {
    const unsigned int want = expected_grey(rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2]);
    same = grey24[k] == want && grey32[k] == want && grey_image.bitmap[k] == want;
  }
  TEST("RGB24, RGBa (alpha ignored) and vpImage<vpRGBa> follow the same rule", same, true);

  vpImage<vpRGBa> back;
  vpImageConvert::convert(grey_image, back);
  TEST("grey to vpRGBa copies the level into R, G, B with opaque alpha",
       back.bitmap[7] == vpRGBa(grey_image.bitmap[7], grey_image.bitmap[7], grey_image.bitmap[7], 255), true);
}

void test_strided_rows() {
  const unsigned int rows = 60, cols = 84;
  vpImage<uint16_t> frame(rows, cols);
  uint32_t seed = 99;
  for (unsigned int k = 0; k < frame.getSize(); ++k) frame.bitmap[k] = static_cast<uint16_t>(next_random(seed));
  vpImage<unsigned char> full;
  vpImageConvert::RGB565ToGrey(frame, full);
  bool by_rule = full.getHeight() == rows && full.getWidth() == cols;
  for (unsigned int k = 0; k < frame.getSize() && by_rule; ++k)
    by_rule = full.bitmap[k] == vpImageConvert::rgb565ToGrey(frame.bitmap[k]);
  TEST("the whole-frame form takes the frame's size and converts each pixel by the rule", by_rule, true);

  // Rows strided apart on both sides: 7 pixels a row, four a round and three after.
  vpImage<unsigned char> strided(rows, cols, 7);
  vpImageConvert::RGB565ToGrey(reinterpret_cast<const uint8_t*>(frame[5] + 6), 2 * cols, strided[5] + 6, cols, 4, 7);
  bool strided_box_only = true;
  for (unsigned int i = 0; i < rows; ++i)
    for (unsigned int j = 0; j < cols; ++j) {
      const bool inside = i >= 5 && i < 9 && j >= 6 && j < 13;
      strided_box_only = strided_box_only && strided[i][j] == (inside ? full[i][j] : 7);
    }
  TEST("strided rows convert exactly their rows x columns, by the rule", strided_box_only, true);
}

}  // namespace

static void test_image_convert() {
  test_rule();
  test_rgb565();
  test_rgb24_rgba();
  test_strided_rows();
}

TESTMAIN(test_image_convert)
