// SPDX-License-Identifier: BSD-3-Clause
// vcl_string.h gives std::string (upstream's test_string: find, substr, comparison).
#include "testlib/testlib_test.h"
#include "vcl_string.h"

static void test_string() {
  const std::string s = "vnl_vector_fixed";
  TEST("find of \"vector\" is 4", s.find("vector"), 4u);
  TEST("substr(4, 6) is \"vector\"", s.substr(4, 6), std::string("vector"));
  TEST("rfind of '_' is 10", s.rfind('_'), 10u);
  TEST("comparison orders \"vnl\" before \"vnl_\"", std::string("vnl") < std::string("vnl_"), true);
  TEST("+ concatenates", std::string("vcl") + "_" + "string", std::string("vcl_string"));
}

TESTMAIN(test_string)
