// SPDX-License-Identifier: BSD-3-Clause
// vnl_decnum as upstream's test_decnum.cxx: construction from integers, doubles, strings and
// streams; conversions; assignment; comparisons with the infinities; increments; sums and
// differences (a grid checked against long); products (factorials); division and remainder
// (a grid with signs checked against long, large quotients, binomials); digit shifts; and the
// stored form (compactify, expand). Also upstream's documented mantissa rules for / and %.
#include <limits>
#include <sstream>
#include <string>

#include "big_number_checks.h"
#include "testlib/testlib_test.h"
#include "vnl/vnl_decnum.h"
#include "vnl/vnl_decnum_traits.h"

namespace {
vnl_decnum read(const std::string& text) { return big_number_checks::read<vnl_decnum>(text); }

void run_constructor_tests() {
  TEST("vnl_decnum(0L)", vnl_decnum(0L), 0L);
  TEST("vnl_decnum(-1L)", vnl_decnum(-1L), -1L);
  TEST("vnl_decnum(0x7fffffffL)", vnl_decnum(0x7fffffffL), 0x7fffffffL);
  TEST("vnl_decnum(-0x7fffffffL)", vnl_decnum(-0x7fffffffL), -0x7fffffffL);
  TEST("vnl_decnum(0xf00000L)", vnl_decnum(0xf00000L), 0xf00000);
  TEST("vnl_decnum(0.0)", vnl_decnum(0.0), 0L);
  TEST("vnl_decnum(-1.0)", vnl_decnum(-1.0), -1L);
  TEST("vnl_decnum(-1234.)", vnl_decnum(-1234.), -1234L);
  TEST("vnl_decnum(1234e3)", vnl_decnum(1234e3), 1234000L);
  TEST("vnl_decnum(1234e-3) * 1000", long(vnl_decnum(1234e-3) * "1000"), 1234L);
  TEST("vnl_decnum(1.234) * 1000", long(vnl_decnum(1.234) * "1000"), 1234L);
  TEST("vnl_decnum(+infinity)", vnl_decnum(std::numeric_limits<double>::infinity()) == vnl_decnum("+Inf"), true);
  TEST("\"-1\"", vnl_decnum("-1"), -1L);
  TEST("\"+1\"", vnl_decnum("+1"), 1L);
  TEST("\"123e5\"", vnl_decnum("123e5"), 12300000L);
  TEST("\"-123e+4\"", vnl_decnum("-123e+4"), -1230000L);
  std::ostringstream s;
  s << vnl_decnum("-1e120") << ' ';
  TEST("\"-1e120\" prints as -1e120", s.str(), "-1e120 ");
  TEST("\"00\"", vnl_decnum("00"), 0L);
  TEST("\"012334567\" is decimal", vnl_decnum("012334567"), 12334567L);
  TEST("\" 9\"", vnl_decnum(" 9"), 9L);
  TEST("\"1.50\" is 150e-2", vnl_decnum("1.50").data() == "150" && vnl_decnum("1.50").exp() == -2, true);
  TEST("\"0.05\" is 5e-2", vnl_decnum("0.05").data() == "5" && vnl_decnum("0.05").exp() == -2, true);
  TEST("\"0.00\" is zero", vnl_decnum("0.00").sign(), ' ');
  TEST("isfinite(-123)", vnl_math::isfinite(vnl_decnum("-123")), true);
  TEST("isfinite(1e999)", vnl_math::isfinite(vnl_decnum("1e999")), true);
  TEST("isfinite(NaN), isnan(NaN)", !vnl_math::isfinite(vnl_decnum("NaN")) && vnl_math::isnan(vnl_decnum("NaN")), true);
  TEST("isnan(1e999)", vnl_math::isnan(vnl_decnum("1e999")), false);
  TEST("\"+Inf\", \"Infinity\", \"-Infin\" are infinite",
       !vnl_math::isfinite(vnl_decnum("+Inf")) && !vnl_math::isfinite(vnl_decnum("Infinity")) &&
           !vnl_math::isfinite(vnl_decnum("-Infin")) && !vnl_math::isnan(vnl_decnum("Inf")),
       true);
  TEST("stream \"+1\"", read("+1"), 1L);
  TEST("stream \"-1\"", read("-1"), -1L);
  TEST("stream \"123e5\"", read("123e5"), 12300000L);
  TEST("stream \"-123e+4\"", read("-123e+4"), -1230000L);
  TEST("stream \" 9\"", read(" 9"), 9L);
  TEST("stream \"-Infinity\"", read("-Infinity"), vnl_decnum("-Inf"));
  std::istringstream two("12.5 -3\n");
  vnl_decnum a, b;
  two >> a >> b;
  TEST("stream reads one number at a time", a == "125e-1" && b == -3L, true);
  TEST("copy", vnl_decnum(vnl_decnum(100L)), 100L);
}

void run_conversion_tests() {
  TEST("int(0)", int(vnl_decnum(0L)), 0);
  TEST("int(-0x7fffffff)", int(vnl_decnum(-0x7fffffffL)), -0x7fffffff);
  vnl_decnum b(0x7fffffffL);
  ++b;
  TEST("++0x7fffffff as unsigned long", (unsigned long)b, 0x80000000UL);
  --b;
  TEST("and back", long(b), 0x7fffffffL);
  TEST("long(12.9) truncates", long(vnl_decnum("12.9")), 12L);
  TEST("long(+Inf), long(-Inf)",
       long(vnl_decnum("+Inf")) == 0x7fffffffL && long(vnl_decnum("-Inf")) == -0x7fffffffL - 1, true);
  TEST("string(-12e-3)", std::string(vnl_decnum("-12e-3")), "-12e-3");
  TEST("string(NaN)", std::string(vnl_decnum("NaN")), "NaN");
}

void run_assignment_tests() {
  vnl_decnum b1;
  TEST_RUN("b1 = 0xffffL", b1 = 0xffffL, long(b1), 0xffffL);
  TEST_RUN("b1 = -0x7fffffffL", b1 = -0x7fffffffL, long(b1), -0x7fffffff);
  TEST_RUN("b1 = \"123456789\"", b1 = "123456789", long(b1), 123456789L);
  const vnl_decnum b5(0x1ffffL);
  TEST_RUN("b1 = b5", b1 = b5, b1, b5);
}

void run_comparison_tests() {
  const vnl_decnum values[] = {vnl_decnum("-Inf"), vnl_decnum(-0x7fffL), vnl_decnum("-1.5"),  vnl_decnum(0L),
                               vnl_decnum(1L),     vnl_decnum("12e-1"),  vnl_decnum(0x7fffL), vnl_decnum("+Inf")};
  TEST("==, !=, <, >, <=, >= on -Inf < -0x7fff < -1.5 < 0 < 1 < 12e-1 < 0x7fff < +Inf",
       big_number_checks::order_errors(values), 0);
  TEST("1000 == 1e3", vnl_decnum("1000") == vnl_decnum("1e3"), true);
  const vnl_decnum nan("NaN");
  TEST("NaN equals nothing, not even NaN", !(nan == nan) && !(nan < vnl_decnum(1L)) && !(vnl_decnum(1L) < nan), true);
}

void run_addition_subtraction_tests() {
  int add_errors = 0, sub_errors = 0;
  for (long i = 1; i < 0xffff; i *= -3) {
    for (long j = 1; j < 0xffff; j *= -3) {
      add_errors += vnl_decnum(i) + vnl_decnum(j) != vnl_decnum(i + j);
      sub_errors += vnl_decnum(i) - vnl_decnum(j) != vnl_decnum(i - j);
    }
  }
  TEST("bi + bj == i + j over a grid of signs", add_errors, 0);
  TEST("bi - bj == i - j over a grid of signs", sub_errors, 0);
  big_number_checks::check_sums_with_infinities<vnl_decnum>();
  const vnl_decnum b1000000(1000000L), b10e12("1000000000000");
  const vnl_decnum zillion("1000000000000000000000000000000000000");
  TEST("1e36 + 10^6", zillion + b1000000, b10e12 * b10e12 * b10e12 + b1000000);
  TEST("+Inf + -Inf is NaN", vnl_math::isnan(vnl_decnum("+Inf") + vnl_decnum("-Inf")), true);
  TEST("1.5 + 25e-2 keeps the smaller exponent", std::string(vnl_decnum("1.5") + vnl_decnum("25e-2")), "175e-2");
}

void run_multiplication_tests() {
  big_number_checks::check_products<vnl_decnum>();
  TEST("0 * Inf is NaN", vnl_math::isnan(vnl_decnum(0L) * vnl_decnum("+Inf")), true);
  TEST("12e-1 * 5e2 == 6e2", vnl_decnum("12e-1") * vnl_decnum("5e2"), 600L);
}

void run_division_tests() {
  TEST("0 / 1", long(vnl_decnum(0L) / vnl_decnum(1L)), 0L);
  TEST("-1 / 1", long(vnl_decnum(-1L) / vnl_decnum(1L)), -1L);
  TEST("-1 / +Inf", long(vnl_decnum(-1L) / vnl_decnum("+Inf")), 0L);
  TEST("+Inf / -1", vnl_decnum("+Inf") / (-1L), vnl_decnum("-Inf"));
  TEST("-1 / 0", vnl_decnum(-1L) / 0L, vnl_decnum("-Inf"));
  TEST("0 / 0 is NaN", vnl_math::isnan(vnl_decnum(-0L) / 0L), true);
  TEST("7 % 0 is 7", vnl_decnum(7L) % 0L, 7L);
  int div_errors = 0, mod_errors = 0;
  for (long i = 0xffff; i != 0; i /= -16) {
    for (long k = -6; k < 9; k += 3) {
      for (long j = 0xffff; j != 0; j /= -16) {
        for (long l = -4; l < 9; l += 3) {  // j + l is never 0
          const vnl_decnum bi(i + k), bj(j + l);
          div_errors += bi / bj != vnl_decnum((i + k) / (j + l));
          mod_errors += bi % bj != vnl_decnum((i + k) % (j + l));
        }
      }
    }
  }
  TEST("(i+k) / (j+l) over a grid of signs", div_errors, 0);
  TEST("(i+k) % (j+l) over a grid of signs", mod_errors, 0);
  // Upstream's documented mantissa rules.
  TEST("42e-3 / 30e-4 == 1e1", vnl_decnum("42e-3") / vnl_decnum("30e-4"), 10L);
  TEST("42e-3 / 3e-3 == 14", vnl_decnum("42e-3") / vnl_decnum("3e-3"), 14L);
  TEST("42e-3 % 30e-4 == 12e-3", vnl_decnum("42e-3") % vnl_decnum("30e-4"), vnl_decnum("12e-3"));
  TEST("42e-3 % 3e-3 == 0", vnl_decnum("42e-3") % vnl_decnum("3e-3"), 0L);
}

void run_shift_tests() {
  const vnl_decnum b1(1L), p_inf("+Inf"), m_inf("-Inf");
  bool left_ok = true;
  long power = 1;
  for (int s = 0; s <= 6; ++s, power *= 10) left_ok = left_ok && long(b1 << s) == power && long(-b1 << s) == -power;
  TEST("1 << s is 10^s, s = 0..6", left_ok, true);
  TEST("1 << 78", b1 << 78, vnl_decnum("1e78"));
  TEST("-1 << 78", -b1 << 78, vnl_decnum("-1e78"));
  TEST("+Inf << 16", p_inf << 16, p_inf);
  TEST("1 << -16 truncates to 0", long(b1 << -16), 0);
  const vnl_decnum b2("1e78");
  TEST("1e78 >> 1", b2 >> 1, vnl_decnum("1e77"));
  TEST("1e78 >> 70", long(b2 >> 70), 100000000L);
  TEST("1e78 >> 78 is 1, >> 79 and >> 99 are 0", long(b2 >> 78) == 1 && long(b2 >> 79) == 0 && long(b2 >> 99) == 0,
       true);
  TEST("-1e78 >> 70", long(-b2 >> 70), -100000000L);
  TEST("-Inf >> 16", m_inf >> 16, m_inf);
}

void run_normalisation_tests() {
  vnl_decnum a("-1e10");
  vnl_decnum b = a;
  TEST("-1e10 is stored as 1 and an exponent", a.data() == "1" && a.exp() == 10 && a.sign() == '-', true);
  a += 1L;
  a -= 1L;
  TEST("+1 -1 expands it to 10000000000", a.data(), "10000000000");
  TEST("the same number", a, b);
  a.compactify();
  TEST("compactify gives 1e10 again", a.data() == "1" && a.exp() == 10, true);
  a.expand();
  TEST("expand gives 10000000000 again", a.data(), "10000000000");
  TEST("still the same number", a, b);
}

void run_rounding_tests() {
  const vnl_decnum x("-12.5"), y("12.5");
  TEST("trunc(-12.5)", x.trunc(), -12L);
  TEST("floor(-12.5), ceil(-12.5)", floor(x) == -13L && ceil(x) == -12L, true);
  TEST("floor(12.5), ceil(12.5)", floor(y) == 12L && ceil(y) == 13L, true);
  TEST("trunc(0.05)", vnl_decnum("0.05").trunc(), 0L);
  TEST("pow(-3, 5)", pow(vnl_decnum(-3L), 5), -243L);
  TEST("vnl_math::sgn", vnl_math::sgn(x) == -1 && vnl_math::sgn(vnl_decnum(0L)) == 0, true);
  TEST("traits maxval is +Inf", vnl_numeric_traits<vnl_decnum>::maxval, vnl_decnum("+Inf"));
}
}  // namespace

static void test_decnum() {
  run_constructor_tests();
  run_conversion_tests();
  run_assignment_tests();
  run_comparison_tests();
  big_number_checks::check_increments<vnl_decnum>();
  run_addition_subtraction_tests();
  run_multiplication_tests();
  run_division_tests();
  big_number_checks::check_large_division<vnl_decnum>();
  run_shift_tests();
  run_normalisation_tests();
  run_rounding_tests();
}

TESTMAIN(test_decnum)
