// SPDX-License-Identifier: BSD-3-Clause
// vnl_finite_int as upstream's test_finite.cxx (its vnl_finite_int part): arithmetic modulo N,
// units and their inverses, zero divisors, orders, the totient, generators, exp and log.
#include "testlib/testlib_test.h"
#include "vnl/vnl_finite.h"

static void test_finite() {
  using Z7 = vnl_finite_int<7>;
  using Z12 = vnl_finite_int<12>;
  TEST("cardinality", Z7::cardinality(), 7u);
  TEST("-1 is 6 mod 7", int(Z7(-1)), 6);
  TEST("5 + 4 = 2 mod 7", Z7(5) + Z7(4), Z7(2));
  TEST("3 - 5 = 5 mod 7", Z7(3) - Z7(5), Z7(5));
  TEST("3 * 5 = 1 mod 7", Z7(3) * Z7(5), Z7(1));
  TEST("1 / 3 = 5 mod 7", Z7(1) / Z7(3), Z7(5));
  TEST("every nonzero element mod 7 is a unit", Z7(4).is_unit() && Z7::is_field(), true);
  TEST("4 is a zero divisor mod 12", Z12(4).is_zero_divisor(), true);
  TEST("5 is a unit mod 12 and its own inverse", Z12(5).reciproc(), Z12(5));
  TEST("Z_12 is not a field", Z12::is_field(), false);
  TEST("totient(12) = 4", Z12::totient(), 4u);
  TEST("additive order of 4 mod 12 is 3", Z12(4).additive_order(), 3u);
  TEST("multiplicative order of 2 mod 7 is 3", Z7(2).multiplicative_order(), 3);
  TEST("a zero divisor has no multiplicative order", Z12(6).multiplicative_order(), -1);
  TEST("3 generates the units mod 7", Z7::smallest_generator(), Z7(3));
  TEST("exp(4) = 3^4 = 4 mod 7", Z7::exp(4), Z7(4));
  TEST("log(4) = 4", Z7(4).log(), 4u);
  TEST("pow(-1) is the inverse", Z7(3).pow(-1), Z7(5));
  TEST("12 = 2 * 2 * 3", Z12::decompose() == std::vector<unsigned>({2, 2, 3}), true);
}

TESTMAIN(test_finite)
