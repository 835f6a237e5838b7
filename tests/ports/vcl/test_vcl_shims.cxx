// SPDX-License-Identifier: BSD-3-Clause
// The vcl shims give the values the platform's own functions and constants would.
#include <cmath>
#include <ctime>

#include "testlib/testlib_test.h"
#include "vcl/vcl_cmath.h"
#include "vcl/vcl_compiler.h"

static void test_vcl_shims() {
  TEST_NEAR("M_PI is pi", M_PI, std::acos(-1.0), 1e-15);
  TEST_NEAR("M_PI_2 is pi/2", M_PI_2, std::acos(-1.0) / 2, 1e-15);
  TEST_NEAR("M_PI_4 is pi/4", M_PI_4, std::acos(-1.0) / 4, 1e-15);
  std::time_t stored = 0;
  const std::time_t returned = vcl_time(&stored);
  TEST("vcl_time stores what it returns", stored, returned);
  TEST_NEAR("vcl_time agrees with time() within two seconds", static_cast<double>(returned),
            static_cast<double>(std::time(nullptr)), 2.0);
}

TESTMAIN(test_vcl_shims)
