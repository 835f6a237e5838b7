// SPDX-License-Identifier: BSD-3-Clause
// Grey conversions follow the documented rounding rule; on-demand conversion equals the full one.
#include <cmath>
#include <cstdint>

#include "testlib/testlib_test.h"
#include "visp3/core/vpImageConvert.h"

static void test_vpImageConvert() {
  TEST("RGB565 white is grey 255", vpImageConvert::rgb565ToGrey(0xFFFF), 255);
  TEST("RGB565 black is grey 0", vpImageConvert::rgb565ToGrey(0x0000), 0);
  // Every RGB565 value is within half a level (plus the integer weights' error) of BT.709 luma.
  double worst = 0;
  for (unsigned int p = 0; p < 65536; ++p) {
    const unsigned int r5 = p >> 11, g6 = (p >> 5) & 63, b5 = p & 31;
    const double r = (r5 << 3 | r5 >> 2), g = (g6 << 2 | g6 >> 4), b = (b5 << 3 | b5 >> 2);
    const double luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    worst = std::fmax(worst, std::fabs(vpImageConvert::rgb565ToGrey(static_cast<uint16_t>(p)) - luma));
  }
  TEST("every RGB565 grey rounds BT.709 luma to nearest", worst <= 0.5 + 0.03, true);

  vpImage<vpRGBa> rgba(3, 4, vpRGBa(10, 200, 30));
  vpImage<unsigned char> grey;
  vpImageConvert::convert(rgba, grey);
  TEST("RGBa to grey keeps the size", grey.getHeight() == 3 && grey.getWidth() == 4, true);
  TEST("RGBa to grey applies the rule", grey[2][3], vpImageConvert::rgbToGrey(10, 200, 30));

  vpImage<uint16_t> frame(37, 53);
  for (unsigned int n = 0; n < frame.getSize(); ++n) frame.bitmap[n] = static_cast<uint16_t>(n * 2654435761u >> 7);
  vpImage<unsigned char> full;
  vpImageConvert::RGB565ToGrey(frame, full);
  vpGreyOnDemand on_demand;
  on_demand.setFrame(frame);
  on_demand.require(5, 9, 20, 30);  // tile rows 0-2, tile columns 1-3
  TEST_EQUAL("on demand converts the whole 8x8 tiles covering the box", on_demand.convertedPixels(), 9u * 64u);
  bool same = true;
  for (int i = 5; i < 20; ++i)
    for (int j = 9; j < 30; ++j) same = same && on_demand.grey()[i][j] == full[i][j];
  TEST("on demand grey equals full conversion inside the box", same, true);
  on_demand.require(6, 10, 12, 12);
  TEST_EQUAL("tiles already converted this frame are not converted again", on_demand.convertedPixels(), 9u * 64u);
  on_demand.setFrame(frame);
  on_demand.require(30, 48, 100, 100);  // rows 24-36 (13), columns 48-52 (5) inside the frame
  TEST_EQUAL("edge tiles convert only their pixels inside the frame", on_demand.convertedPixels(), 13u * 5u);
}

TESTMAIN(test_vpImageConvert)
