// SPDX-License-Identifier: BSD-3-Clause
// vcl_limits.h gives std::numeric_limits with IEEE values (upstream's test_limits).
#include <cmath>

#include "testlib/testlib_test.h"
#include "vcl_limits.h"

static void test_limits() {
  TEST("int has 31 value digits", std::numeric_limits<int>::digits, 31);
  TEST("double has 53 mantissa digits", std::numeric_limits<double>::digits, 53);
  TEST("float has 24 mantissa digits", std::numeric_limits<float>::digits, 24);
  TEST("double epsilon is 2^-52", std::numeric_limits<double>::epsilon(), std::ldexp(1.0, -52));
  TEST("double has infinity", std::numeric_limits<double>::has_infinity, true);
  TEST("infinity is larger than max", std::numeric_limits<double>::infinity() > std::numeric_limits<double>::max(),
       true);
  TEST("quiet NaN is not equal to itself",
       std::numeric_limits<double>::quiet_NaN() == std::numeric_limits<double>::quiet_NaN(), false);
}

TESTMAIN(test_limits)
