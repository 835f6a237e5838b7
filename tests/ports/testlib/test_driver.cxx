// SPDX-License-Identifier: BSD-3-Clause
// The testlib driver: upstream's testlib tests, and ours that check testlib counts honestly.
#include "testlib/testlib_register.h"

DECLARE(test_assert);
DECLARE(test_macros);
DECLARE(test_args);
DECLARE(test_root_dir);
DECLARE(test_testlib_counts);
DECLARE(test_testlib_macros);

void register_tests() {
  REGISTER(test_assert);
  REGISTER(test_macros);
  REGISTER(test_args);
  REGISTER(test_root_dir);
  REGISTER(test_testlib_counts);
  REGISTER(test_testlib_macros);
}

DEFINE_MAIN
