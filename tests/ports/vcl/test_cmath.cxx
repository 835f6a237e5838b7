// SPDX-License-Identifier: BSD-3-Clause
// vcl_cmath.h gives <cmath> and the M_PI constants (upstream's test_cmath: abs, sqrt, overloads).
#include "testlib/testlib_test.h"
#include "vcl_cmath.h"

static void test_cmath() {
  TEST("std::abs(int)", std::abs(-3), 3);
  TEST("std::abs(long)", std::abs(-3L), 3L);
  TEST("std::abs(float)", std::abs(-3.5f), 3.5f);
  TEST("std::abs(double)", std::abs(-3.5), 3.5);
  TEST_NEAR("std::sqrt(2.0)", std::sqrt(2.0), 1.41421356237309504880, 1e-15);
  TEST_NEAR("std::sqrt(2.0f) is float", std::sqrt(2.0f), 1.41421356f, 1e-6);
  TEST_NEAR("M_PI", M_PI, 3.14159265358979323846, 1e-15);
  TEST("std::isnan of NaN", std::isnan(std::nan("")), true);
}

TESTMAIN(test_cmath)
