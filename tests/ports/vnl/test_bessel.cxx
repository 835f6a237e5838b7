// SPDX-License-Identifier: BSD-3-Clause
// vnl_bessel as upstream's test_bessel.cxx: known values of J_0, J_1, J_2, all orders at once,
// and the parity of J_n for negative x.
#include "testlib/testlib_test.h"
#include "vnl/vnl_bessel.h"

static void test_bessel() {
  TEST_NEAR("J_0(0) = 1", vnl_bessel0(0.0), 1.0, 1e-15);
  TEST_NEAR("J_0(1)", vnl_bessel0(1.0), 0.76519768655796655, 1e-14);
  TEST_NEAR("J_1(2)", vnl_bessel(1, 2.0), 0.57672480775687339, 1e-14);
  TEST_NEAR("J_2(5)", vnl_bessel(2, 5.0), 0.046565116277752215, 1e-14);
  TEST_NEAR("J_0 at its first zero", vnl_bessel0(2.4048255576957728), 0.0, 1e-14);
  vnl_vector<double> J;
  vnl_bessel(4, 3.0, J);
  TEST("all orders 0..4", J.size(), 5u);
  TEST_NEAR("J_3(3) among them", J[3], 0.30906272225525164, 1e-14);
  TEST_NEAR("recurrence J_1 + J_3 = (4/x) J_2", J[1] + J[3], 4 / 3.0 * J[2], 1e-14);
  TEST_NEAR("J_1(-2) = -J_1(2)", vnl_bessel(1, -2.0), -0.57672480775687339, 1e-14);
  TEST_NEAR("J_2(-5) = J_2(5)", vnl_bessel(2, -5.0), 0.046565116277752215, 1e-14);
}

TESTMAIN(test_bessel)
