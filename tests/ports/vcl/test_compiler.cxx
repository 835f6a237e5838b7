// SPDX-License-Identifier: BSD-3-Clause
// vcl_compiler.h's macros expand as upstream's (upstream's test_compiler checks the configuration).
#include <string>

#include "testlib/testlib_test.h"
#include "vcl_compiler.h"
#include "vcl_deprecated.h"

namespace {
int count_args(int, int) { return 2; }
}  // namespace

static void test_compiler() {
  TEST("VXL_VERSION_MAJOR is 5", VXL_VERSION_MAJOR, 5);
  TEST("VXL_LEGACY_FUTURE_REMOVE is off, as upstream's default", VXL_LEGACY_FUTURE_REMOVE, 0);
  TEST("VCL_COMMA separates macro arguments", count_args(1 VCL_COMMA 2), 2);
  int used = 0;
  VXL_USED_IN_DEBUG(used = 1;)
#ifdef NDEBUG
  TEST("VXL_USED_IN_DEBUG drops its argument with NDEBUG", used, 0);
#else
  TEST("VXL_USED_IN_DEBUG keeps its argument without NDEBUG", used, 1);
#endif
  VXL_DEPRECATED_MACRO("test_compiler");  // silent unless VXL_WARN_DEPRECATED is defined
  TEST("VXL_DEPRECATED_MACRO compiles as a statement", true, true);
}

TESTMAIN(test_compiler)
