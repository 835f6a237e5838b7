// SPDX-License-Identifier: BSD-3-Clause
// TEST and TEST_RUN as upstream's test_macros.cxx uses them: TEST_RUN runs its statement first.
#include "testlib/testlib_test.h"

namespace {
int value_set_by_statement = 0;
void set_value() { value_set_by_statement = 1; }
}  // namespace

MAIN(test_macros) {
  START("macros");
  TEST("TEST macro", 5, 5);
  TEST_RUN("TEST_RUN runs the statement, then compares", set_value(), value_set_by_statement, 1);
  SUMMARY();
}
