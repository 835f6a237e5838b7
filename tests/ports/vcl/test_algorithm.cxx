// SPDX-License-Identifier: BSD-3-Clause
// vcl_algorithm.h gives the standard algorithms (upstream's vcl/tests/test_algorithm.cxx sorts).
#include "testlib/testlib_test.h"
#include "vcl_algorithm.h"
#include "vcl_vector.h"

static void test_algorithm() {
  std::vector<double> v = {3.0, -1.0, 2.5, 0.0};
  std::sort(v.begin(), v.end());
  TEST("std::sort through vcl_algorithm.h orders the values", v[0] == -1.0 && v[3] == 3.0, true);
  TEST("std::find finds 2.5 at index 2", std::find(v.begin(), v.end(), 2.5) - v.begin(), 2);
  TEST("std::max_element is 3", *std::max_element(v.begin(), v.end()), 3.0);
}

TESTMAIN(test_algorithm)
