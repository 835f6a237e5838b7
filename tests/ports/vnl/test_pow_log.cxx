// SPDX-License-Identifier: BSD-3-Clause
// Integer powers by repeated squaring and the integer base-8 logarithm, as upstream's
// test_pow_log.cxx: upstream tests its own helpers (the algorithms behind vnl's integer power
// code); we test ours, written the same way, on int and double as upstream and also on the
// configured real.
#include <climits>

#include "real/real.h"
#include "testlib/testlib_test.h"

namespace {
/// a^b by squaring (wraps around for results beyond int, which the test avoids).
int int_pow(int a, unsigned int b) {
  if (b == 0) return 1;
  if (b == 1) return a;
  const long long square = static_cast<long long>(a) * a;
  return static_cast<int>(static_cast<long long>(int_pow(static_cast<int>(square), b / 2)) * int_pow(a, b % 2));
}

/// a^b for any integer b (1 / a^-b when b < 0), on double or real.
template <class T>
T scalar_pow(T a, int b) {
  if (b == 0) return T(1);
  if (b == 1) return a;
  if (b < 0) return scalar_pow(T(1) / a, -b);
  return scalar_pow(a * a, b / 2) * scalar_pow(a, b % 2);
}

/// floor(log_8 a); INT_MIN stands for minus infinity at a = 0.
int log8(unsigned int a) {
  if (a == 0) return INT_MIN;
  int r = 0;
  for (; a >= 8; a >>= 3) ++r;
  return r;
}

void test_int_pow() {
  TEST("exponent 0", int_pow(-33, 0U), 1);
  TEST("exponent 1", int_pow(-33, 1U), -33);
  TEST("any power of 1", int_pow(1, 12345U), 1);
  TEST("even power of -1", int_pow(-1, 12346U), 1);
  TEST("odd power of -1", int_pow(-1, 12345U), -1);
  TEST("2^30", int_pow(2, 30U), 0x40000000);
  TEST("(-19)^7", int_pow(-19, 7U), -893871739);
}

void test_dbl_pow() {
  TEST("exponent 0", scalar_pow(-33.3, 0), 1.0);
  TEST("exponent 1", scalar_pow(-33.3, 1), -33.3);
  TEST("exponent -1", scalar_pow(0.4, -1), 2.5);
  TEST("even power of -1", scalar_pow(-1.0, 12346), 1.0);
  TEST("odd power of -1", scalar_pow(-1.0, 12345), -1.0);
  TEST("(-23)^7", scalar_pow(-23.0, 7), -3404825447.0);
  TEST_NEAR("1.00000001^900", scalar_pow(1.00000001, 900), 1.000009000040455, 1e-13);
  TEST_NEAR("(-10)^300", scalar_pow(-10.0, 300), 1e300, 1e285);
  TEST_NEAR("(-10)^-300", scalar_pow(-10.0, -300), 1e-300, 1e-313);
}

void test_real_pow() {
  TEST("real: exponent 0", scalar_pow(real(-33), 0), real(1));
  TEST("real: (-3)^5", scalar_pow(real(-3), 5), real(-243));
  TEST("real: odd power of -1", scalar_pow(real(-1), 12345), real(-1));
  TEST("real: (1/2)^10 = 2^-10", scalar_pow(real(1) / real(2), 10), real(1) / real(1024));
  TEST("real: 2^-3 = 1/8", scalar_pow(real(2), -3), real(1) / real(8));
  TEST("real: 10^6", scalar_pow(real(10), 6), real(1000000));
}

void test_log() {
  TEST("log8(1)", log8(1), 0);
  TEST("log8(2)", log8(2), 0);
  TEST("log8(7)", log8(7), 0);
  TEST("log8(8)", log8(8), 1);
  TEST("log8(9)", log8(9), 1);
  TEST("log8(60)", log8(60), 1);
  TEST("log8(64)", log8(64), 2);
  TEST("log8(69)", log8(69), 2);
  TEST("log8(500)", log8(500), 2);
  TEST("log8(511)", log8(511), 2);
  TEST("log8(512)", log8(512), 3);
  TEST("log8(0x7fffffff)", log8(0x7fffffff), 10);
  TEST("log8(0) stands for minus infinity", log8(0) < -0x7fffffffL, true);
}
}  // namespace

static void test_pow_log() {
  test_int_pow();
  test_dbl_pow();
  test_real_pow();
  test_log();
}

TESTMAIN(test_pow_log)
