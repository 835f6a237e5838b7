// SPDX-License-Identifier: BSD-3-Clause
// vcl_vector.h gives std::vector (upstream's test_vector: growth, contiguity, bool vectors).
#include "testlib/testlib_test.h"
#include "vcl_vector.h"

static void test_vector() {
  std::vector<int> v;
  for (int i = 0; i < 100; ++i) v.push_back(i);
  TEST("100 push_backs give size 100", v.size(), 100u);
  TEST("elements are contiguous", &v[99] - &v[0], 99);
  v.resize(10);
  TEST("resize shrinks", v.size(), 10u);
  std::vector<bool> flags(5, false);
  flags[2] = true;
  TEST("vector<bool> stores a flag", flags[2] && !flags[1], true);
}

TESTMAIN(test_vector)
