// SPDX-License-Identifier: BSD-3-Clause
// A failing check must make the summary fail, and a program that checks nothing must fail too.
#include <cstdio>

#include "testlib/testlib_test.h"

int test_testlib_counts_main(int, char*[]) {  // its own main: it restarts the tally
  testlib_test_start("inner run with one failure");
  testlib_test_assert("a deliberately failing check", false);
  testlib_test_assert("a passing check", true);
  const int failing_summary = testlib_test_summary();

  testlib_test_start("inner run that checks nothing");
  const int empty_summary = testlib_test_summary();

  testlib_test_start("inner run that passes");
  TEST("one equals one", 1, 1);
  const int passing_summary = testlib_test_summary();

  std::printf("The three inner runs above are expected: one failure, one empty, one pass.\n");
  testlib_test_start("test_testlib_counts");
  TEST("summary of a run with a failure is non-zero", failing_summary != 0, true);
  TEST("summary of a run with no checks is non-zero", empty_summary != 0, true);
  TEST("summary of a passing run is zero", passing_summary, 0);
  return testlib_test_summary();
}
