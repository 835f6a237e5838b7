// SPDX-License-Identifier: BSD-3-Clause
/// kth_smallest against std::nth_element: every k of arrays of many sizes (below and above the
/// insertion-sort cut and the two-pivot rounds' start), with repeated numbers, sorted, reversed
/// and all-equal inputs, in double and float; the number at k must be the same. The same for
/// kth_of_values (the pose step's and the drift gate's medians) in the build's `real`.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "edgetrack/order_statistic.h"
#include "real/real.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// A small linear congruential generator: the same numbers on every host and under QEMU.
struct Numbers {
  uint32_t state;
  uint32_t next() { return state = state * 1664525u + 1013904223u; }
};

/// How many k of `input` where `kth` (kth_smallest or kth_of_values) and nth_element disagree.
template <class T>
int disagreements(const std::vector<T>& input, T (*kth)(T*, size_t, size_t)) {
  int bad = 0;
  for (size_t k = 0; k < input.size(); ++k) {
    std::vector<T> expected = input, values = input;
    std::nth_element(expected.begin(), expected.begin() + static_cast<std::ptrdiff_t>(k), expected.end());
    bad += kth(values.data(), values.size(), k) != expected[k];
  }
  return bad;
}

template <class T>
void check_type(const char* type, T (*kth)(T*, size_t, size_t)) {
  Numbers numbers{12345u};
  int bad_random = 0, bad_repeated = 0, bad_ordered = 0;
  // Every third size up to 70, then sizes of a frame's matches (two-pivot rounds above 32).
  std::vector<size_t> sizes;
  for (size_t n = 1; n <= 70; n += 3) sizes.push_back(n);
  for (size_t n : {97, 181, 256}) sizes.push_back(n);
  for (size_t n : sizes) {
    std::vector<T> random(n), repeated(n), sorted(n), reversed(n), equal(n, T(2.5));
    for (size_t i = 0; i < n; ++i) {
      random[i] = static_cast<T>(numbers.next() % 100000u) / T(1000);
      repeated[i] = static_cast<T>(numbers.next() % 5u);
      sorted[i] = static_cast<T>(i);
      reversed[i] = static_cast<T>(n - i);
    }
    bad_random += disagreements(random, kth);
    bad_repeated += disagreements(repeated, kth);
    bad_ordered += disagreements(sorted, kth) + disagreements(reversed, kth) + disagreements(equal, kth);
  }
  std::printf("%s:\n", type);
  TEST_EQUAL("random numbers: the same k-th as nth_element at every k", bad_random, 0);
  TEST_EQUAL("five values repeated: the same k-th at every k", bad_repeated, 0);
  TEST_EQUAL("sorted, reversed and all equal: the same k-th at every k", bad_ordered, 0);
}

}  // namespace

static void test_order_statistic() {
  check_type<double>("double", &kth_smallest<double>);
  check_type<float>("float", &kth_smallest<float>);
  check_type<real>("kth_of_values, real", &kth_of_values<real>);
}

TESTMAIN(test_order_statistic)
