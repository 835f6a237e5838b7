// SPDX-License-Identifier: BSD-3-Clause
// Exposure schedules give the factors they say, clip as a sensor saturates, and refuse bad
// schedules; JPEG at quality 50 changes a frame by a bounded amount, more than at quality 95.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "camera_response.h"
#include "testlib/testlib_test.h"

using namespace edgetrack_app;

namespace {

/// A frame with what JPEG finds hard and easy: a colour ramp, a sharp bright square, fine stripes.
RgbImage test_card() {
  RgbImage image = make_image(96, 64);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<uint8_t>(40 + x);
      p[1] = static_cast<uint8_t>(60 + y);
      p[2] = static_cast<uint8_t>(90);
      if (x >= 20 && x < 44 && y >= 16 && y < 40) std::fill_n(p, 3, 230);
      if (x >= 60 && (x / 2) % 2 == 0) std::fill_n(p, 3, 20);
    }
  return image;
}

struct Difference {
  double mean = 0;
  int largest = 0;
};

Difference difference(const RgbImage& a, const RgbImage& b) {
  Difference d;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    const int e = std::abs(int(a.rgb[i]) - int(b.rgb[i]));
    d.mean += e;
    d.largest = std::max(d.largest, e);
  }
  d.mean /= a.rgb.size();
  return d;
}

}  // namespace

static void test_camera_response() {
  auto step = ExposureSchedule::parse("0:1,29:1,30:1.4");
  TEST("a step schedule reads", step.ok(), true);
  if (step.ok()) {
    TEST_NEAR("before the step: 1", step.value().factor(29), 1.0, 1e-12);
    TEST_NEAR("from the step on: 1.4", step.value().factor(30), 1.4, 1e-12);
    TEST_NEAR("after the last key: its factor", step.value().factor(500), 1.4, 1e-12);
  }
  auto ramp = ExposureSchedule::parse("10:0.6,20:1");
  TEST("a ramp schedule reads", ramp.ok(), true);
  if (ramp.ok()) {
    TEST_NEAR("before the first key: its factor", ramp.value().factor(0), 0.6, 1e-12);
    TEST_NEAR("half way: half way between the factors", ramp.value().factor(15), 0.8, 1e-12);
  }
  for (const char* bad : {"", "5:1,5:1.2", "9:1,3:1", "0:0", "0:-1", "0:17", "0:nan", "0:1,", "0", "a:1", "0:1x"})
    TEST((std::string("refused: '") + bad + "'").c_str(), ExposureSchedule::parse(bad).ok(), false);

  RgbImage levels = make_image(3, 1);
  levels.rgb = {0, 50, 100, 150, 180, 182, 183, 200, 255};
  apply_exposure(levels, 1.4);
  const std::vector<uint8_t> brighter = {0, 70, 140, 210, 252, 255, 255, 255, 255};
  TEST("40 % brighter: each level times 1.4, rounded, saturating at 255", levels.rgb == brighter, true);
  apply_exposure(levels, 0.5);
  TEST("then half: 0 35 70 105 126 128 ...", levels.rgb[1] == 35 && levels.rgb[4] == 126 && levels.rgb[5] == 128, true);

  const RgbImage card = test_card();
  auto q50 = jpeg_round_trip(card, 50), q95 = jpeg_round_trip(card, 95);
  TEST("JPEG round trips at quality 50 and 95", q50.ok() && q95.ok(), true);
  if (q50.ok() && q95.ok()) {
    const Difference d50 = difference(card, q50.value()), d95 = difference(card, q95.value());
    std::printf("JPEG: quality 50 changes a level by %.2f on average, %d at most; quality 95 by %.2f, %d\n", d50.mean,
                d50.largest, d95.mean, d95.largest);
    TEST("the decoded frame has the frame's size", q50.value().width == card.width && q50.value().height == card.height, true);
    TEST("quality 50 leaves artefacts", d50.mean > 0.5, true);
    TEST("bounded: under 6 grey levels on average", d50.mean < 6, true);
    TEST("quality 95 changes the frame less", d95.mean < d50.mean && d95.largest < d50.largest, true);
  }
}

TESTMAIN(test_camera_response);
