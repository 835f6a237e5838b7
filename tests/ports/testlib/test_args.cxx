// SPDX-License-Identifier: BSD-3-Clause
// The driver hands a test its own name and the arguments after it (upstream's test_args.cxx):
// CTest runs `testlib_test_all test_args one two` and `testlib_test_all all one two`.
#include <string>

#include "testlib/testlib_test.h"

MAIN_ARGS(test_args) {
  START("argument passing");
  TEST("argument count is 3", argc, 3);
  if (argc >= 1) {
    testlib_test_begin("argv[0] is the test name, or \"all\"");
    testlib_test_perform(std::string("test_args") == argv[0] || std::string("all") == argv[0]);
  }
  if (argc >= 2) TEST("argv[1] is \"one\"", std::string("one"), argv[1]);
  if (argc >= 3) TEST("argv[2] is \"two\"", std::string("two"), argv[2]);
  SUMMARY();
}
