// SPDX-License-Identifier: BSD-3-Clause
/// vpMe: upstream's defaults, and the geometry of the oriented masks (antisymmetry, the mirror
/// and quarter-turn relations between orientations, the axis-aligned masks) and mask indexing.
#include <cmath>
#include <cstdlib>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "visp3/me/vpMe.h"

namespace {

void test_defaults() {
  const vpMe me;
  TEST_NEAR("threshold 1500", static_cast<double>(me.getThreshold()), 1500, 0);
  TEST_NEAR("mu1 0.5", static_cast<double>(me.getMu1()), 0.5, 0);
  TEST_NEAR("mu2 0.5", static_cast<double>(me.getMu2()), 0.5, 0);
  TEST_NEAR("min sample step 4", static_cast<double>(me.getMinSampleStep()), 4, 0);
  TEST_NEAR("sample step 10", static_cast<double>(me.getSampleStep()), 10, 0);
  TEST_EQUAL("range 4", me.getRange(), 4u);
  TEST_EQUAL("mask size 5", me.getMaskSize(), 5u);
  TEST_EQUAL("180 masks", me.getMaskNumber(), 180u);
  TEST_EQUAL("angle step 1 degree", me.getAngleStep(), 1u);
  TEST_EQUAL("strip 2", me.getStrip(), 2);
  TEST_EQUAL("points to track 500", me.getPointsToTrack(), 500);
}

/// True when every mask k satisfies mask[k][a][b] == -mask[k][n-1-a][n-1-b] (point antisymmetry).
bool antisymmetric(const vpMe& me) {
  const int n = static_cast<int>(me.getMaskSize());
  for (unsigned int k = 0; k < me.getMaskNumber(); ++k)
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        if (me.getMask()[k][a][b] != -me.getMask()[k][n - 1 - a][n - 1 - b]) return false;
  return true;
}

void test_geometry(unsigned int size) {
  vpMe me;
  me.setMaskSize(size);
  const int n = static_cast<int>(size);
  TEST("point antisymmetric about the centre, every orientation", antisymmetric(me), true);

  bool bounded = true;
  for (unsigned int k = 0; k < 180; ++k)
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) bounded = bounded && std::abs(me.getMask()[k][a][b]) <= 100;
  TEST("weights within [-100, 100]", bounded, true);

  // Theta 0: the edge is the centre row; rows below it weigh +100, rows above -100.
  bool horizontal = true;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const int want = 2 * a + 1 == n ? 0 : (2 * a + 1 > n ? 100 : -100);
      horizontal = horizontal && me.getMask()[0][a][b] == want;
    }
  TEST("mask 0 is -100 above the centre row, 0 on it, +100 below", horizontal, true);

  // A quarter turn: mask[k + 90][a][b] == mask[k][n-1-b][a].
  bool quarter = true;
  for (unsigned int k = 0; k < 90; ++k)
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) quarter = quarter && me.getMask()[k + 90][a][b] == me.getMask()[k][n - 1 - b][a];
  TEST("mask k + 90 is mask k turned a quarter", quarter, true);

  // A mirror about the vertical axis: mask[180 - k][a][b] == -mask[k][a][n-1-b].
  bool mirror = true;
  for (unsigned int k = 1; k < 180; ++k)
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) mirror = mirror && me.getMask()[180 - k][a][b] == -me.getMask()[k][a][n - 1 - b];
  TEST("mask 180 - k is mask k mirrored left-right and negated", mirror, true);
}

void test_known_weights() {
  const vpMe me;
  // Theta 45: the diagonal through the centre cuts the diagonal pixels in half (weight 0), and
  // the pixels beside them only touch the line at a corner (weight +-100).
  TEST_EQUAL("45 degrees: centre 0", static_cast<int>(me.getMask()[45][2][2]), 0);
  TEST_EQUAL("45 degrees: pixel on the diagonal 0", static_cast<int>(me.getMask()[45][1][1]), 0);
  TEST_EQUAL("45 degrees: pixel beside the diagonal 100", std::abs(me.getMask()[45][1][2]), 100);
  TEST_EQUAL("45 degrees: corner away from the diagonal 100", std::abs(me.getMask()[45][0][4]), 100);
  TEST("45 degrees: opposite sides have opposite signs",
       me.getMask()[45][1][2] == -me.getMask()[45][2][1] && me.getMask()[45][1][2] != 0, true);
  // 90 degrees: columns left of the centre +100, right -100.
  TEST_EQUAL("90 degrees: left column +100", static_cast<int>(me.getMask()[90][3][0]), 100);
  TEST_EQUAL("90 degrees: right column -100", static_cast<int>(me.getMask()[90][3][4]), -100);
}

void test_index() {
  vpMe me;
  TEST_EQUAL("normal -pi/2 (tangent 0) uses mask 0", me.maskIndex(real(-M_PI / 2)), 0u);
  TEST_EQUAL("normal 0 (tangent 90 degrees) uses mask 90", me.maskIndex(real(0)), 90u);
  TEST_EQUAL("normal pi/2 (tangent 180 = 0 degrees) uses mask 0", me.maskIndex(real(M_PI / 2)), 0u);
  TEST_EQUAL("normal pi/4 uses mask 135", me.maskIndex(real(M_PI / 4)), 135u);
  TEST_EQUAL("normal -pi/4 uses mask 45", me.maskIndex(real(-M_PI / 4)), 45u);
  TEST_EQUAL("normal pi + 0.1 folds like 0.1", me.maskIndex(real(M_PI + 0.1)), me.maskIndex(real(0.1)));
  TEST_EQUAL("normal 0.3 rad (17.19 deg) rounds to mask 107", me.maskIndex(real(0.3)), 107u);

  me.setMaskNumber(18);
  TEST_EQUAL("18 masks: angle step 10", me.getAngleStep(), 10u);
  TEST_EQUAL("18 masks: 107 degrees uses mask 10", me.maskIndex(real(0.3)), 10u);
  TEST_EQUAL("18 masks: 179 degrees uses the last mask", me.maskIndex(real(M_PI / 2 - 0.0175)), 17u);
  TEST("18 masks: mask 9 is the 90 degree mask", me.getMask()[9][0][0] == 100 && me.getMask()[9][0][4] == -100,
       true);
  TEST("18 masks: still antisymmetric", antisymmetric(me), true);
}

}  // namespace

static void test_me_masks() {
  test_defaults();
  test_geometry(5);
  test_geometry(7);
  test_geometry(4);
  test_known_weights();
  test_index();
}

TESTMAIN(test_me_masks)
