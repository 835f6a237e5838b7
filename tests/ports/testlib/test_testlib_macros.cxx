// SPDX-License-Identifier: BSD-3-Clause
// TEST_NEAR, TEST_NEAR_REL, TEST_FAR and TEST_EQUAL decide as upstream's do.
#include <cmath>
#include <limits>
#include <string>

#include "testlib/testlib_test.h"

static void test_testlib_macros() {
  // First, in a scratch tally, the assertion helpers must reject what they should.
  testlib_test_start("scratch run, three failures expected");
  testlib_test_assert_near("far apart", 1.0, 2.0, 0.5);
  testlib_test_assert_near("NaN is never near", std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0);
  testlib_test_assert_near_relative("relative miss", 1.1, 1.0, 0.01);
  const int scratch_summary = testlib_test_summary();

  testlib_test_start("test_testlib_macros");
  TEST("near/relative helpers fail when they must", scratch_summary != 0, true);
  TEST("TEST compares with ==", 2 + 2, 4);
  TEST_EQUAL("TEST_EQUAL compares strings", std::string("vnl"), std::string("vnl"));
  TEST_NEAR("TEST_NEAR accepts a difference at the tolerance", 1.0 + 1e-9, 1.0, 1e-9 * 1.0001);
  TEST_NEAR_REL("TEST_NEAR_REL scales with the values", 1e6 + 1.0, 1e6, 2e-6);
  TEST_FAR("TEST_FAR rejects close values", 1.0, 1.5, 0.25);
}

TESTMAIN(test_testlib_macros)
