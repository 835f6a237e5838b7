// SPDX-License-Identifier: BSD-3-Clause
// vnl_bignum as upstream's test_bignum.cxx: construction from integers, doubles, strings in
// every literal form and streams; conversions back; assignment; addition and subtraction
// (a grid checked against long), increments, products (factorials), division and remainder
// (a grid checked against long, and large quotients), shifts, comparisons with the
// infinities, and vnl_bignum_to_string for every integer type's extremes.
#include <climits>
#include <limits>
#include <sstream>
#include <string>

#include "big_number_checks.h"
#include "testlib/testlib_test.h"
#include "vnl/vnl_bignum.h"
#include "vnl/vnl_bignum_traits.h"

namespace {
vnl_bignum read(const std::string& text) { return big_number_checks::read<vnl_bignum>(text); }

template <class T>
void check_to_string(T value) {
  std::string text;
  vnl_bignum_to_string(text, vnl_bignum(value));
  TEST(("to_string(" + std::to_string(value) + ")").c_str(), text, std::to_string(value));
}
template <class T>
void check_to_string_extremes() {
  check_to_string(std::numeric_limits<T>::max());
  check_to_string(std::numeric_limits<T>::min());
  bool digits_ok = true;
  for (int i = 0; i < 10; ++i) {
    std::string text;
    digits_ok = digits_ok && vnl_bignum_to_string(text, vnl_bignum(static_cast<T>(i))) == std::to_string(i);
  }
  TEST("to_string of the decimal digits", digits_ok, true);
}

void run_constructor_tests() {
  TEST("vnl_bignum(0L)", vnl_bignum(0L), 0L);
  TEST("vnl_bignum(-1L)", vnl_bignum(-1L), -1L);
  TEST("vnl_bignum(-0x7fffffffL)", vnl_bignum(-0x7fffffffL), -0x7fffffffL);
  TEST("vnl_bignum(0xf00000L)", vnl_bignum(0xf00000L), 0xf00000);
  TEST("vnl_bignum(LONG_MAX)", vnl_bignum(LONG_MAX), LONG_MAX);
  TEST("vnl_bignum(LONG_MIN)", vnl_bignum(LONG_MIN), LONG_MIN);
  const double dmax = vnl_numeric_traits<double>::maxval;
  TEST("double(vnl_bignum(0.0))", double(vnl_bignum(0.0)), 0.0);
  TEST("double(vnl_bignum(-1.0))", double(vnl_bignum(-1.0)), -1.0);
  TEST("double(vnl_bignum(double max))", double(vnl_bignum(dmax)), dmax);
  TEST("double(vnl_bignum(-double max))", double(vnl_bignum(-dmax)), -dmax);
  TEST("double(vnl_bignum(-1234567e3))", double(vnl_bignum(-1234567e3)), -1234567e3);
  TEST("vnl_bignum(double(0xf00000))", vnl_bignum(double(0xf00000)), 0xf00000);
  TEST("vnl_bignum(2.75) truncates", vnl_bignum(2.75), 2);
  TEST("long double(vnl_bignum(1234567e3L))", (long double)vnl_bignum(1234567e3L), 1234567e3L);

  TEST("\"-1\"", vnl_bignum("-1"), -1L);
  TEST("\"+1\"", vnl_bignum("+1"), 1L);
  TEST("\"123\"", vnl_bignum("123"), 123L);
  TEST("\"123e5\"", vnl_bignum("123e5"), 12300000L);
  TEST("\"-123e+4\"", vnl_bignum("-123e+4"), -1230000L);
  TEST("\"123e12\"", double(vnl_bignum("123e12")), 123e12);
  std::ostringstream big;
  big << vnl_bignum("-1e120");
  TEST("\"-1e120\" prints as -1 and 120 zeros", big.str(), "-1" + std::string(120, '0'));
  TEST("\"0x0\"", vnl_bignum("0x0"), 0);
  TEST("\"0xf\" and \"0xF\"", vnl_bignum("0xf") == 15 && vnl_bignum("0xF") == 15, true);
  TEST("\"0x1aF\"", vnl_bignum("0x1aF"), 0x1af);
  TEST("\"00\"", vnl_bignum("00"), 0);
  TEST("\"012334567\" is octal", vnl_bignum("012334567"), 012334567);
  TEST("\" 9\"", vnl_bignum(" 9"), 9);
  TEST("\"1234L\"", vnl_bignum("1234L"), 1234);
  TEST("\"+Inf\"", vnl_bignum("+Inf").is_plus_infinity(), true);
  TEST("\"Infinity\"", vnl_bignum("Infinity").is_plus_infinity(), true);
  TEST("\"-Infin\"", vnl_bignum("-Infin").is_minus_infinity(), true);
  TEST("\"12x\" is no number: 0", vnl_bignum("12x"), 0);

  TEST("stream \"+1\"", read("+1"), 1L);
  TEST("stream \"-1\"", read("-1"), -1L);
  TEST("stream \"123e5\"", read("123e5"), 12300000L);
  TEST("stream \"123e+4\"", read("123e+4"), 1230000L);
  TEST("stream \"0x1aF\"", read("0x1aF"), 0x1af);
  TEST("stream \"012334567\"", read("012334567"), 012334567);
  TEST("stream \" 9\"", read(" 9"), 9L);
  TEST("stream \"-Inf\"", read("-Inf").is_minus_infinity(), true);
  std::istringstream two("12 34");
  vnl_bignum a, b;
  two >> a >> b;
  TEST("stream reads one number at a time", a == 12 && b == 34, true);
  TEST("copy", long(vnl_bignum(vnl_bignum(100L))), 100L);
}

void run_conversion_tests() {
  TEST("short(0x7fff)", short(vnl_bignum(0x7fffL)), 0x7fff);
  TEST("short(-0x8000)", short(vnl_bignum(-0x8000L)), short(-0x8000));
  TEST("int(0x7fffffff)", int(vnl_bignum(0x7fffffffL)), 0x7fffffff);
  TEST("int(-0x7fffffff)", int(vnl_bignum(-0x7fffffffL)), -0x7fffffff);
  vnl_bignum b(0x7fffffffL);
  ++b;
  TEST("++0x7fffffff as unsigned long", (unsigned long)long(b), 0x80000000UL);
  --b;
  TEST("and back", long(b), 0x7fffffffL);
  ++b;
  b = -b;
  TEST("-0x80000000", long(b), -0x7fffffffL - 1L);
  const float fmax = vnl_numeric_traits<float>::maxval;
  TEST("float(99999)", float(vnl_bignum(99999.0)), 99999.0f);
  TEST("float(float max)", float(vnl_bignum(fmax)), fmax);
  TEST("float(-float max)", float(vnl_bignum(-fmax)), -fmax);
  TEST("float(+Inf)", float(vnl_bignum("+Inf")), std::numeric_limits<float>::infinity());
  b = vnl_numeric_traits<double>::maxval;
  ++b;
  TEST("double max + 1 is finite", b.is_infinity(), false);
  TEST("double(1e300)", double(vnl_bignum(1e300)), 1e300);
  TEST("double(-1e300)", double(vnl_bignum(-1e300)), -1e300);
  TEST("double(float max)", double(vnl_bignum(fmax)), double(fmax));
  TEST("double(-Inf)", double(vnl_bignum("-Inf")), -std::numeric_limits<double>::infinity());
  TEST("long(+Inf) is 0, as upstream", long(vnl_bignum("+Inf")), 0L);
  vnl_bignum d(20);
  vnl_bignum_from_string(d, "1000");
  TEST("vnl_bignum_from_string", d, vnl_bignum(1000));
  vnl_bignum_from_string(d, "-Inf");
  TEST("vnl_bignum_from_string(\"-Inf\")", d.is_minus_infinity(), true);
}

void run_assignment_tests() {
  vnl_bignum b1;
  TEST_RUN("b1 = 0xffffL", b1 = 0xffffL, long(b1), 0xffffL);
  TEST_RUN("b1 = -1.23e6", b1 = -1.23e6, double(b1), -1.23e6);
  TEST_RUN("b1 = -0x7fffffffL", b1 = -0x7fffffffL, long(b1), -0x7fffffff);
  TEST_RUN("b1 = \"0x1fffff\"", b1 = "0x1fffff", long(b1), 0x1fffffL);
  const vnl_bignum b5(0x1ffffL);
  TEST_RUN("b1 = b5", b1 = b5, b1, b5);
}

void run_addition_subtraction_tests() {
  long add_errors = 0, sub_errors = 0;
  for (long i = 1; i < 0xfffffff; i *= 3) {
    for (long j = 1; j < 0xfffffff; j *= 3) {
      add_errors += vnl_bignum(i) + vnl_bignum(j) != vnl_bignum(i + j);
      sub_errors += vnl_bignum(i) - vnl_bignum(j) != vnl_bignum(i - j);
    }
  }
  TEST("bi + bj == i + j over a grid", add_errors, 0);
  TEST("bi - bj == i - j over a grid", sub_errors, 0);
  big_number_checks::check_sums_with_infinities<vnl_bignum>();
  TEST("zillion - -Inf", vnl_bignum("1e18") - vnl_bignum("-Inf"), vnl_bignum("+Inf"));
  const vnl_bignum b3 = "12345e30";
  std::ostringstream dumped;
  b3.dump(dumped);
  TEST("dump shows the value", dumped.str().find("12345" + std::string(30, '0')) != std::string::npos, true);
}

void run_increment_tests() {
  TEST("default is 0", vnl_bignum(), 0);
  big_number_checks::check_increments<vnl_bignum>();
  vnl_bignum inf("Infinity");
  TEST("++Inf and --Inf stay +Inf", (++inf, --inf, inf.is_plus_infinity()), true);
  vnl_bignum m_inf("-Infinity");
  TEST("++-Inf stays -Inf", (++m_inf).is_minus_infinity(), true);
}

void run_division_tests() {
  TEST("0 / 1", long(vnl_bignum(0L) / vnl_bignum(1L)), 0L);
  TEST("-1 / 1", long(vnl_bignum(-1L) / vnl_bignum(1L)), -1L);
  TEST("-1 / +Inf", long(vnl_bignum(-1L) / vnl_bignum("+Inf")), 0L);
  TEST("+Inf / -1", vnl_bignum("+Inf") / (-1L), vnl_bignum("-Inf"));
  TEST("-1 / 0", vnl_bignum(-1L) / 0L, vnl_bignum("-Inf"));
  TEST("7 % +Inf is 7", vnl_bignum(7) % vnl_bignum("+Inf"), 7);
  TEST("7 % 0 is 0", vnl_bignum(7) % 0L, 0);
  TEST("-7 / 2 truncates, -7 % 2 takes the dividend's sign", vnl_bignum(-7) / 2 == -3 && vnl_bignum(-7) % 2 == -1,
       true);
  long div_errors = 0, mod_errors = 0;
  for (long i = 0xffffff; i > 0; i /= 0x10) {
    for (long j = 0x7ffffff; j > 0; j /= 0x10) {
      for (long k = 1; k < 17; ++k) {
        for (long l = 1; l < 17; ++l) {
          const vnl_bignum b1(i + k), b2(j + l);
          div_errors += b1 / b2 != vnl_bignum((i + k) / (j + l));
          mod_errors += b1 % b2 != vnl_bignum((i + k) % (j + l));
        }
      }
    }
  }
  TEST("(i+k) / (j+l) over a grid", div_errors, 0);
  TEST("(i+k) % (j+l) over a grid", mod_errors, 0);
}

void run_large_division_tests() {
  big_number_checks::check_large_division<vnl_bignum>();
  vnl_bignum a = "0X989680", b = "0X989681";
  TEST("0x5AF31112D680 / 0x989681", (a * b) / vnl_bignum("0X989681"), a);
}

void run_shift_tests() {
  const vnl_bignum b1(1L), p_inf("+Inf"), m_inf("-Inf");
  bool left_ok = true;
  for (int s = 0; s <= 30; ++s) left_ok = left_ok && long(b1 << s) == (1L << s) && long(-b1 << s) == -(1L << s);
  TEST("1 << s and -1 << s for s = 0..30", left_ok, true);
  TEST("1 << 32", b1 << 32, vnl_bignum("4294967296"));
  TEST("-1 << 32", -b1 << 32, vnl_bignum("-4294967296"));
  TEST("+Inf << 16", p_inf << 16, p_inf);
  TEST("1 << -16 is 0", long(b1 << -16), 0);
  const vnl_bignum b2("4294967296");
  bool right_ok = true;
  for (int s = 1; s <= 30; ++s) right_ok = right_ok && long(b2 >> (s + 2)) == (1L << 30) >> s;
  TEST("2^32 >> s", right_ok, true);
  TEST("2^32 >> 1", b2 >> 1, vnl_bignum("2147483648"));
  TEST("2^32 >> 32 is 1, >> 33 and >> 67 are 0", long(b2 >> 32) == 1 && long(b2 >> 33) == 0 && long(b2 >> 67) == 0,
       true);
  TEST("-2^32 >> 1 shifts the magnitude", -b2 >> 1, vnl_bignum("-2147483648"));
  TEST("-2^32 >> 32 is -1, >> 33 is 0", long(-b2 >> 32) == -1 && long(-b2 >> 33) == 0, true);
  TEST("-Inf >> 16", m_inf >> 16, m_inf);
}

void run_comparison_tests() {
  const vnl_bignum values[] = {vnl_bignum("-Inf"),  vnl_bignum(-0x7fffL), vnl_bignum(0L),    vnl_bignum(1L),
                               vnl_bignum(0x7fffL), vnl_bignum("1e30"),   vnl_bignum("+Inf")};
  TEST("==, !=, <, >, <=, >= on -Inf < -0x7fff < 0 < 1 < 0x7fff < 1e30 < +Inf", big_number_checks::order_errors(values),
       0);
  TEST("comparison with long", vnl_bignum(5) < 6L && 6L > vnl_bignum(5) && vnl_bignum(5) == 5L, true);
  TEST("comparison with double", vnl_bignum(5) < 5.5 && vnl_bignum(5) == 5.0, true);
  TEST("abs", vnl_bignum(-12).abs(), 12);
}
}  // namespace

static void test_bignum() {
  run_constructor_tests();
  run_conversion_tests();
  run_assignment_tests();
  run_addition_subtraction_tests();
  run_increment_tests();
  big_number_checks::check_products<vnl_bignum>();
  run_division_tests();
  run_large_division_tests();
  run_shift_tests();
  run_comparison_tests();
  check_to_string_extremes<signed char>();
  check_to_string_extremes<unsigned char>();
  check_to_string_extremes<short>();
  check_to_string_extremes<unsigned short>();
  check_to_string_extremes<int>();
  check_to_string_extremes<unsigned int>();
  check_to_string_extremes<long>();
  check_to_string_extremes<unsigned long>();
  check_to_string_extremes<long long>();
  check_to_string_extremes<unsigned long long>();
}

TESTMAIN(test_bignum)
