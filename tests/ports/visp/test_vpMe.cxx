// SPDX-License-Identifier: BSD-3-Clause
// vpMe has upstream's defaults, and its masks are antisymmetric edge detectors of the right angle.
#include "testlib/testlib_test.h"
#include "visp3/me/vpMe.h"

static void test_vpMe() {
  vpMe me;
  TEST_NEAR("default threshold is 1500", me.getThreshold(), 1500, 0);
  TEST_NEAR("default mu1 is 0.5", me.getMu1(), 0.5, 0);
  TEST_NEAR("default mu2 is 0.5", me.getMu2(), 0.5, 0);
  TEST("default range is 4", me.getRange(), 4u);
  TEST("default mask size is 5", me.getMaskSize(), 5u);
  TEST("default mask number is 180", me.getMaskNumber(), 180u);
  TEST("default strip is 2", me.getStrip(), 2);
  TEST_NEAR("default sample step is 10", me.getSampleStep(), 10, 0);

  // Mask 0 (horizontal edge line): rows above are -100, the middle row 0, rows below +100.
  const vpMeMask m0 = me.getMask()[0];
  TEST("mask 0 top row is -100", m0[0][2], -100);
  TEST("mask 0 middle row is 0", m0[2][4], 0);
  TEST("mask 0 bottom row is +100", m0[4][0], 100);
  // Mask 90 (vertical edge line): columns left +100, right -100.
  const vpMeMask m90 = me.getMask()[90];
  TEST("mask 90 left column is +100", m90[1][0], 100);
  TEST("mask 90 right column is -100", m90[3][4], -100);
  bool antisymmetric = true;
  for (unsigned int k = 0; k < 180; ++k)
    for (unsigned int a = 0; a < 5; ++a)
      for (unsigned int b = 0; b < 5; ++b)
        antisymmetric = antisymmetric && me.getMask()[k][a][b] == -me.getMask()[k][4 - a][4 - b];
  TEST("every mask is antisymmetric about its centre", antisymmetric, true);

  TEST("normal angle 0 uses the 90 degree mask", me.maskIndex(0), 90u);
  TEST("normal angle pi/2 uses mask 0", me.maskIndex(real(1.5707963267948966)), 0u);
  me.setMaskNumber(90);
  TEST("90 masks give a 2 degree step", me.getAngleStep(), 2u);
  TEST("normal angle 0 then uses mask 45", me.maskIndex(0), 45u);
}

TESTMAIN(test_vpMe)
