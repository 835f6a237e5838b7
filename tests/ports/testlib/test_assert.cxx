// SPDX-License-Identifier: BSD-3-Clause
// The assertion functions accept what upstream's test_assert.cxx checks they accept, and the
// complex and integer forms decide the same way.
#include <complex>

#include "testlib/testlib_test.h"

static void test_assert() {
  testlib_test_assert("Assert: true passes", true);
  testlib_test_assert_near("Assert near: 1.2345 is within 0.001 of 1.2346", 1.2345, 1.2346, 0.001);
  testlib_test_assert_near_relative("Assert near relative: 1.235e20 within 0.1% of 1.236e20", 1.235e20, 1.236e20,
                                    0.001);
  testlib_test_assert_far("Assert far: 1.235 is farther than 0.001 from 1.237", 1.235, 1.237, 0.001);
  const std::complex<double> a(1.0, 2.0);
  testlib_test_assert_near("complex near: |(1,2) - (1,2.0005)| <= 0.001", a, std::complex<double>(1.0, 2.0005), 0.001);
  testlib_test_assert_near_relative("complex near relative", a * 1e10, std::complex<double>(1e10, 2.0001e10), 1e-4);
  testlib_test_assert_far("complex far: (1,2) is 1 from (1,3)", a, std::complex<double>(1.0, 3.0), 0.5);
  testlib_test_assert_equal("integer equal: 42 == 42", 42L, 42L);
  TEST_NEAR("TEST_NEAR takes complex values", a, std::complex<double>(1.0, 2.0), 0.0);
  Assert("Assert alias", true);
  AssertNear("AssertNear alias", 0.5, 0.5 + 1e-13);
  AssertFar("AssertFar alias", 0.5, 1.5, 0.1);
}

TESTMAIN(test_assert)
