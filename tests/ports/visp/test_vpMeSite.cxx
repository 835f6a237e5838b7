// SPDX-License-Identifier: BSD-3-Clause
// vpMeSite finds a vertical step edge along its normal and says why it drops a site.
#include "testlib/testlib_test.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeSite.h"

// Dark left of column `edge`, bright from it on.
static vpImage<unsigned char> step_image(int edge, unsigned char dark, unsigned char bright) {
  vpImage<unsigned char> image(60, 80, dark);
  for (unsigned int i = 0; i < image.getHeight(); ++i)
    for (int j = edge; j < 80; ++j) image[i][j] = bright;
  return image;
}

static void test_vpMeSite() {
  vpMe me;
  me.setRange(7);
  const vpImage<unsigned char> image = step_image(40, 20, 200);
  vpMeSite site;
  site.init(30, 35, 0);  // normal along the columns, 5 px left of the edge
  site.track(image, &me, false);
  TEST("a site within range finds the step", site.getState(), vpMeSite::NO_SUPPRESSION);
  TEST("the found column is on the step", site.get_j() == 39 || site.get_j() == 40, true);
  TEST_NEAR("the found column as a real", site.get_jfloat(), site.get_j(), 0);
  TEST_NEAR("the row does not move", site.get_ifloat(), 30, 0);
  TEST("the reference contrast is set", site.convlt != 0, true);
  TEST("the previous position is kept in i_1, j_1", site.i_1 == 30 && site.j_1 == 35, true);

  const real found = site.get_jfloat();
  const vpImage<unsigned char> moved = step_image(43, 20, 200);
  site.track(moved, &me);
  TEST_NEAR("the site follows the step 3 px", site.get_jfloat(), found + 3, 0);

  // A ramp gives every candidate a small non-zero response: the likelihood |conv + convlt|
  // passes, the ratio conv / convlt is far below 1 - mu1, and the last candidate is not zero.
  vpImage<unsigned char> ramp(60, 80);
  for (unsigned int i = 0; i < 60; ++i)
    for (unsigned int j = 0; j < 80; ++j) ramp[i][j] = static_cast<unsigned char>(j);
  site.track(ramp, &me);
  TEST("a weak ramp passes the likelihood but fails the contrast test", site.getState(), vpMeSite::CONSTRAST);
  TEST_NEAR("a suppressed site stays where it was", site.get_jfloat(), found + 3, 0);

  const vpImage<unsigned char> flat(60, 80, 128);
  vpMeSite lonely;
  lonely.init(30, 35, 0);
  lonely.track(flat, &me, false);
  TEST("no edge at all is a threshold suppression", lonely.getState(), vpMeSite::THRESHOLD);

  vpMeSite border;
  border.initFromImage(image, &me, 2, 40, 0);
  TEST("a site at the border is too near", border.getState(), vpMeSite::TOO_NEAR);
  vpMeSite direct;
  direct.initFromImage(image, &me, 30, 40, 0);
  TEST("initFromImage keeps the site", direct.getState(), vpMeSite::NO_SUPPRESSION);
  TEST("initFromImage takes the response at the site", direct.convlt != 0, true);

  int top, left, bottom, right;
  direct.getSearchBox(&me, top, left, bottom, right);
  TEST("the search box spans range and half mask along the normal", left == 31 && right == 50, true);
  TEST("the search box spans the mask across the normal", top == 28 && bottom == 33, true);
}

TESTMAIN(test_vpMeSite)
