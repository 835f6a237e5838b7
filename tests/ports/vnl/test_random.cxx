// SPDX-License-Identifier: BSD-3-Clause
// vnl_random as upstream's test_random.cxx: seeding reproduces a sequence, integers and
// doubles stay in range, and the uniform and normal samples have the right mean and spread.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/vnl_random.h"

static void test_random() {
  vnl_random a(42), b(42), c(43);
  bool same = true, differs = false;
  for (int i = 0; i < 100; ++i) {
    const auto x = a.next_uint32();
    same = same && x == b.next_uint32();
    differs = differs || x != c.next_uint32();
  }
  TEST("the same seed gives the same sequence", same, true);
  TEST("another seed gives another sequence", differs, true);
  const auto first = vnl_random(7).next_uint32();
  vnl_random r(7);
  r.next_uint32();
  r.restart();
  TEST("restart() begins the sequence again", r.next_uint32(), first);
  r.reseed(7);
  TEST("reseed(seed) begins the seed's sequence", r.next_uint32(), first);

  vnl_random rng;
  bool in_range = true;
  int hits[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 5000; ++i) {
    const int k = rng.lrand32(-2, 2);
    in_range = in_range && k >= -2 && k <= 2;
    if (k >= -2 && k <= 2) ++hits[k + 2];
  }
  TEST("lrand32(-2, 2) stays in [-2, 2]", in_range, true);
  bool each_value_seen_often = true;
  for (int h : hits) each_value_seen_often = each_value_seen_often && h > 850 && h < 1150;  // 1000 +- 4.7 sigma
  TEST("lrand32(-2, 2) is uniform over its 5 values", each_value_seen_often, true);

  const int n = 20000;
  double sum = 0, sum2 = 0, highest = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.drand64(2.0, 4.0);
    sum += x, sum2 += x * x;
    highest = std::fmax(highest, x);
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  TEST_NEAR("drand64(2, 4) has mean 3", mean, 3.0, 0.02);
  TEST_NEAR("drand64(2, 4) has variance 1/3", var, 1.0 / 3, 0.01);
  TEST("drand64(2, 4) stays below 4", highest < 4.0, true);
  bool unit = true;
  for (int i = 0; i < 1000; ++i) {
    const double x = rng.drand32();
    unit = unit && x >= 0.0 && x < 1.0;
  }
  TEST("drand32() is in [0, 1)", unit, true);

  sum = sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal64();
    sum += x, sum2 += x * x;
  }
  TEST_NEAR("normal64() has mean 0", sum / n, 0.0, 0.04);
  TEST_NEAR("normal64() has variance 1", sum2 / n - (sum / n) * (sum / n), 1.0, 0.05);
  sum = 0;
  for (int i = 0; i < 2000; ++i) sum += rng.normal();
  TEST_NEAR("normal() has mean 0", sum / 2000, 0.0, 0.1);
}

TESTMAIN(test_random)
