// SPDX-License-Identifier: BSD-3-Clause
/// vpImagePoint: i is the row (v), j the column (u); the arithmetic and distances.
#include "real/real.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpImagePoint.h"

static void test_image_point() {
  vpImagePoint p(3, 4);
  TEST_NEAR("i is the first argument", p.get_i(), 3, 0);
  TEST_NEAR("j is the second argument", p.get_j(), 4, 0);
  TEST_NEAR("u is j", p.get_u(), 4, 0);
  TEST_NEAR("v is i", p.get_v(), 3, 0);
  p.set_uv(real(10), real(20));
  TEST_NEAR("set_uv sets j from u", p.get_j(), 10, 0);
  TEST_NEAR("set_uv sets i from v", p.get_i(), 20, 0);
  p.set_ij(real(1.5), real(-2.25));
  TEST_NEAR("set_ij keeps sub-pixel values", p.get_i() + p.get_j(), -0.75, 0);

  const vpImagePoint a(0, 0), b(3, 4);
  TEST_NEAR("distance 3-4-5", vpImagePoint::distance(a, b), 5, 1e-6);
  TEST_NEAR("squared distance", vpImagePoint::sqrDistance(a, b), 25, 1e-6);
  const vpImagePoint c = b - vpImagePoint(1, 1);
  TEST("difference", c == vpImagePoint(2, 3), true);
  TEST("sum", (a + b) == b, true);
  TEST("scaling", (b * real(2)) == vpImagePoint(6, 8), true);
  TEST("division", (b / real(2)) == vpImagePoint(real(1.5), real(2)), true);
  vpImagePoint d = b;
  d += vpImagePoint(1, 1);
  d -= vpImagePoint(2, 2);
  TEST("+= and -=", d == vpImagePoint(2, 3), true);
  TEST("!= on different points", a != b, true);
}

TESTMAIN(test_image_point)
