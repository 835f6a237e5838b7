// SPDX-License-Identifier: BSD-3-Clause
// vcl_atomic_count counts up and down and returns the new value (upstream's test_atomic_count).
#include "testlib/testlib_test.h"
#include "vcl_atomic_count.h"

static void test_atomic_count() {
  vcl_atomic_count count(0);
  TEST("starts at its initial value", static_cast<long>(count), 0L);
  TEST("++ returns the new value", ++count, 1L);
  TEST("++ again", ++count, 2L);
  TEST("-- returns the new value", --count, 1L);
  TEST("-- to zero", --count, 0L);
  TEST("reads 0 at the end", static_cast<long>(count), 0L);
}

TESTMAIN(test_atomic_count)
