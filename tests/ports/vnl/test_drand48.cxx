// SPDX-License-Identifier: BSD-3-Clause
// vnl_drand48 as upstream's test_drand48.cpp: for each seed, vnl_srand48 + vnl_drand48 give
// exactly the C library's srand48 + drand48 numbers (upstream compares the first number of
// seeds 0..9999; we compare the first numbers of 2000 seeds and a longer run of a few, and
// check the range [0, 1)).
#include <cstdlib>

#include "testlib/testlib_test.h"
#include "vnl/vnl_drand48.h"

static void test_drand48() {
  long first_mismatches = 0;
  for (long seed = 0; seed < 2000; ++seed) {
    srand48(seed);
    vnl_srand48(seed);
    if (drand48() != vnl_drand48()) ++first_mismatches;
  }
  TEST("the first number of seeds 0..1999 is the C library's", first_mismatches, 0);

  long run_mismatches = 0;
  bool in_range = true;
  for (const long seed : {-1L, 12345L, 0x7fffffffL, -0x7fffffffL - 1}) {
    srand48(seed);
    vnl_srand48(seed);
    for (int i = 0; i < 500; ++i) {
      const double x = vnl_drand48();
      in_range = in_range && x >= 0.0 && x < 1.0;
      if (drand48() != x) ++run_mismatches;
    }
  }
  TEST("500 numbers after negative and extreme seeds are the C library's", run_mismatches, 0);
  TEST("every number is in [0, 1)", in_range, true);

  vnl_srand48(7);
  const double a = vnl_drand48(), b = vnl_drand48();
  vnl_srand48(7);
  TEST("reseeding restarts the sequence", vnl_drand48() == a && vnl_drand48() == b, true);
}

TESTMAIN(test_drand48)
