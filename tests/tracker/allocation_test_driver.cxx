// SPDX-License-Identifier: BSD-3-Clause
/// The allocation test's driver: a separate executable because it replaces operator new.
#include "testlib/testlib_register.h"

DECLARE(test_tracker_allocations);
DECLARE(test_tracker_allocations_along_a_sequence);
DECLARE(test_tracker_limits);

void register_tests() {
  REGISTER(test_tracker_allocations);
  REGISTER(test_tracker_allocations_along_a_sequence);
  REGISTER(test_tracker_limits);
}

DEFINE_MAIN
