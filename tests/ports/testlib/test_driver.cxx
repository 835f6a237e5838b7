// SPDX-License-Identifier: BSD-3-Clause
// The testlib driver: checks that testlib itself counts and reports honestly.
#include "testlib/testlib_register.h"

DECLARE(test_testlib_counts);
DECLARE(test_testlib_macros);

void register_tests() {
  REGISTER(test_testlib_counts);
  REGISTER(test_testlib_macros);
}

DEFINE_MAIN
