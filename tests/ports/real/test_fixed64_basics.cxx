// SPDX-License-Identifier: BSD-3-Clause
// fixed64's construction, conversions, comparisons, rounding functions, numeric_limits and
// saturation counting behave as docs/ARCHITECTURE.md's fixed-point contract says, for S47.16
// and S40.23; and real.h picks the type that EDGETRACK_REAL configured.
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include "fixed64_test_support.h"
#include "real/fixed64.h"
#include "real/real.h"
#include "testlib/testlib_test.h"

namespace {
using fixed64_test::describe;
using fixed64_test::type_name;
using fixedpoint::fixed64;

std::string named(const char* what, const char* type) { return std::string(what) + " (" + type + ")"; }

/// Checks a raw result, printing value and raw hex of both on failure.
template <int F>
void test_raw(const std::string& what, fixed64<F> got, fixed64<F> expected) {
  testlib_test_assert_equal(named(what.c_str(), type_name<F>()), got.raw() == expected.raw(), describe(expected),
                            describe(got));
}

template <int F>
void check_construction_and_conversion() {
  using T = fixed64<F>;
  const char* name = type_name<F>();
  constexpr std::int64_t kOne = std::int64_t{1} << F;
  TEST(named("an int converts exactly", name).c_str(), T(-7).raw(), -7 * kOne);
  TEST(named("the largest int converts exactly", name).c_str(), T(INT32_MAX).raw(), std::int64_t{INT32_MAX} * kOne);
  TEST(named("the smallest int converts exactly", name).c_str(), T(INT32_MIN).raw(), std::int64_t{INT32_MIN} * kOne);
  TEST(named("default construction is zero", name).c_str(), T().raw(), 0);
  TEST(named("from_raw keeps the representation", name).c_str(), T::from_raw(0x123456789abcLL).raw(),
       0x123456789abcLL);
  // From double: constexpr, rounded to nearest, halves away from zero.
  constexpr T kHalf = T(0.5);
  static_assert(kHalf.raw() == kOne / 2, "a constexpr double constant is exact");
  TEST(named("0.5 is half of one", name).c_str(), kHalf.raw(), kOne / 2);
  TEST(named("a double rounds to the nearest ulp", name).c_str(), T(1.0 + 0.7 / kOne).raw(), kOne + 1);
  TEST(named("a double half an ulp up rounds away from zero", name).c_str(), T(0.5 / kOne).raw(), 1);
  TEST(named("a negative double half an ulp down rounds away from zero", name).c_str(), T(-0.5 / kOne).raw(), -1);
  TEST(named("a double just below half an ulp rounds to zero", name).c_str(), T(0.49999999 / kOne).raw(), 0);
  TEST(named("float converts too", name).c_str(), T(0.25f).raw(), kOne / 4);
  TEST(named("long long converts explicitly", name).c_str(), T(1000000LL).raw(), 1000000 * kOne);
  TEST(named("an unsigned size converts explicitly", name).c_str(), T(std::size_t{3}).raw(), 3 * kOne);
  // Out.
  TEST(named("to int truncates toward zero for positives", name).c_str(), static_cast<int>(T(2.75)), 2);
  TEST(named("to int truncates toward zero for negatives", name).c_str(), static_cast<int>(T(-2.75)), -2);
  TEST(named("to int of a value just below zero is zero", name).c_str(), static_cast<int>(T::from_raw(-1)), 0);
  TEST(named("to long long of lowest() is the whole part", name).c_str(),
       static_cast<long long>(std::numeric_limits<T>::lowest()), -(std::int64_t{1} << (63 - F)));
  TEST(named("to int saturates past int's range", name).c_str(), static_cast<int>(std::numeric_limits<T>::max()),
       INT32_MAX);
  TEST(named("to unsigned of a negative is zero", name).c_str(), static_cast<unsigned>(T(-3)), 0u);
  TEST(named("to double is exact for a short value", name).c_str(), static_cast<double>(T(-3.125)), -3.125);
  TEST(named("to float is exact for a short value", name).c_str(), static_cast<float>(T(6.5)), 6.5f);
  TEST_NEAR(named("to double of max() is 2^(63-F)", name).c_str(), static_cast<double>(std::numeric_limits<T>::max()),
            std::ldexp(1.0, 63 - F), std::ldexp(1.0, 63 - F) * 1e-15);
  TEST(named("explicit bool is true for one ulp", name).c_str(), static_cast<bool>(T::from_raw(1)), true);
  TEST(named("explicit bool is false for zero", name).c_str(), static_cast<bool>(T(0)), false);
  for (double v : {0.1, -0.1, 123.456, -98765.4321, 1e-6, 3.0e5}) {
    const T x(v);
    TEST_NEAR(named(("double " + std::to_string(v) + " round-trips within half an ulp").c_str(), name).c_str(),
              static_cast<double>(x), v, 0.5 / kOne);
  }
}

template <int F>
void check_comparisons_and_operators() {
  using T = fixed64<F>;
  const char* name = type_name<F>();
  const T a(1.5), b(-2.25);
  TEST(named("== and !=", name).c_str(), a == T(1.5) && a != b, true);
  TEST(named("< <= > >=", name).c_str(), b < a && b <= a && a > b && a >= b && a <= a && a >= a, true);
  TEST(named("comparison with an int converts the int", name).c_str(), a > 1 && a < 2 && b < 0 && 0 > b, true);
  TEST(named("one ulp apart compares unequal", name).c_str(), T::from_raw(5) < T::from_raw(6), true);
  TEST(named("lowest() < max()", name).c_str(), std::numeric_limits<T>::lowest() < std::numeric_limits<T>::max(),
       true);
  test_raw<F>("x * 2 with an int", a * 2, T(3));
  test_raw<F>("2 * x with an int", 2 * a, T(3));
  test_raw<F>("x + 1", a + 1, T(2.5));
  test_raw<F>("unary minus", -b, T(2.25));
  test_raw<F>("x / 4", b / 4, T(-0.5625));
  T c = a;
  c += b;
  test_raw<F>("+=", c, T(-0.75));
  c -= b;
  test_raw<F>("-=", c, a);
  c *= b;
  test_raw<F>("*=", c, T(-3.375));
  c /= b;
  test_raw<F>("/=", c, a);
  // Rounding of * and /: half an ulp is rounded away from zero.
  const T ulp = T::from_raw(1), half = T(0.5);
  test_raw<F>("ulp * 0.5 rounds half away from zero", ulp * half, ulp);
  test_raw<F>("-ulp * 0.5 rounds half away from zero", -ulp * half, -ulp);
  test_raw<F>("ulp * 0.25 rounds to zero", ulp * T(0.25), T(0));
  // round(n / 3) = floor((2n + 3) / 6) for n >= 0.
  const auto third = [](std::int64_t n) { return T::from_raw((2 * (n << F) + 3) / 6); };
  test_raw<F>("1 / 3 rounds to nearest", T(1) / 3, third(1));
  test_raw<F>("2 / 3 rounds to nearest", T(2) / 3, third(2));
  test_raw<F>("-2 / 3 is -(2 / 3)", T(-2) / 3, -third(2));
  test_raw<F>("1 / -3 is -(1 / 3)", T(1) / -3, -third(1));
}

template <int F>
void check_rounding_functions() {
  using T = fixed64<F>;
  const T max = std::numeric_limits<T>::max(), lowest = std::numeric_limits<T>::lowest();
  const T largest_whole = floor(max);
  struct Case {
    double x, floor, ceil, round;
  };
  for (const Case& c : {Case{2.5, 2, 3, 3}, Case{-2.5, -3, -2, -3}, Case{2.25, 2, 3, 2}, Case{-2.25, -3, -2, -2},
                        Case{2.75, 2, 3, 3}, Case{-2.75, -3, -2, -3}, Case{4, 4, 4, 4}, Case{-4, -4, -4, -4},
                        Case{0, 0, 0, 0}, Case{0.5, 0, 1, 1}, Case{-0.5, -1, 0, -1}}) {
    const T x(c.x);
    const std::string at = " of " + std::to_string(c.x);
    test_raw<F>("floor" + at, floor(x), T(c.floor));
    test_raw<F>("ceil" + at, ceil(x), T(c.ceil));
    test_raw<F>("round" + at, round(x), T(c.round));
    test_raw<F>("abs" + at, abs(x), T(std::fabs(c.x)));
    test_raw<F>("fabs" + at, fabs(x), T(std::fabs(c.x)));
  }
  test_raw<F>("floor of one ulp below zero is -1", floor(T::from_raw(-1)), T(-1));
  test_raw<F>("ceil of one ulp above zero is 1", ceil(T::from_raw(1)), T(1));
  test_raw<F>("floor(lowest) is lowest, a whole number", floor(lowest), lowest);
  test_raw<F>("round(lowest) is lowest", round(lowest), lowest);
  test_raw<F>("ceil(lowest) is lowest", ceil(lowest), lowest);
  const std::uint64_t before = fixedpoint::saturation_count();
  test_raw<F>("floor(max) is the largest whole number", floor(max), T::from_raw(max.raw() & ~((std::int64_t{1} << F) - 1)));
  TEST(named("floor, ceil, round of lowest and floor(max) count nothing", type_name<F>()).c_str(),
       fixedpoint::saturation_count() - before, 0u);
  test_raw<F>("ceil(max) saturates", ceil(max), max);
  test_raw<F>("round(max) saturates to the largest whole number", round(max), largest_whole);
  TEST(named("ceil(max) and round(max) count one saturation each", type_name<F>()).c_str(),
       fixedpoint::saturation_count() - before, 2u);
}

template <int F>
void check_numeric_limits() {
  using T = fixed64<F>;
  using L = std::numeric_limits<T>;
  const char* name = type_name<F>();
  TEST(named("numeric_limits is specialised", name).c_str(), L::is_specialized && L::is_signed && !L::is_integer,
       true);
  TEST(named("numeric_limits is exact and bounded, without infinity or NaN", name).c_str(),
       L::is_exact && L::is_bounded && !L::has_infinity && !L::has_quiet_NaN && !L::is_iec559, true);
  TEST(named("epsilon() is one ulp", name).c_str(), L::epsilon().raw(), 1);
  TEST(named("min() is one ulp", name).c_str(), L::min().raw(), 1);
  TEST(named("max() is the largest raw value", name).c_str(), L::max().raw(), INT64_MAX);
  TEST(named("lowest() is the smallest raw value", name).c_str(), L::lowest().raw(), INT64_MIN);
  TEST(named("round_error() is half an ulp", name).c_str(), L::round_error().raw(), std::int64_t{1} << (F - 1));
  TEST(named("digits counts the 63 magnitude bits", name).c_str(), L::digits, 63);
  TEST(named("round_style is to nearest", name).c_str(), L::round_style, std::round_to_nearest);
  TEST_NEAR(named("epsilon() as double is 2^-F", name).c_str(), static_cast<double>(L::epsilon()),
            std::ldexp(1.0, -F), 0);
}

/// Every overflowing + - * / and every division by zero saturates toward the exact result's sign
/// and adds exactly one to the counter.
template <int F>
void check_saturation_counting() {
  using T = fixed64<F>;
  const char* name = type_name<F>();
  const T max = std::numeric_limits<T>::max(), lowest = std::numeric_limits<T>::lowest();
  const T big = T(1 << 30) * T(1 << (31 - F));  // 2^(61-F): a quarter of the range
  fixedpoint::reset_saturation_count();
  TEST(named("reset_saturation_count clears the counter", name).c_str(), fixedpoint::saturation_count(), 0u);
  struct Case {
    const char* what;
    T got, expected;
  };
  const Case cases[] = {
      {"max + ulp", max + T::from_raw(1), max},
      {"lowest - ulp", lowest - T::from_raw(1), lowest},
      {"lowest + (-ulp)", lowest + T::from_raw(-1), lowest},
      {"max - (-ulp)", max - T::from_raw(-1), max},
      {"big * 4", big * 4, max},
      {"big * -5", big * -5, lowest},
      {"-big * -big", -big * -big, max},
      {"big / 0.125", big / T(0.125), max},
      {"-big / 0.125", -big / T(0.125), lowest},
      {"max / ulp", max / T::from_raw(1), max},
      {"1 / 0", T(1) / 0, max},
      {"-1 / 0", T(-1) / 0, lowest},
      {"0 / 0", T(0) / 0, T(0)},
      {"-lowest", -lowest, max},
      {"abs(lowest)", abs(lowest), max},
  };
  for (const Case& c : cases) test_raw<F>(std::string(c.what) + " saturates", c.got, c.expected);
  TEST(named("each of those counted exactly one saturation", name).c_str(), fixedpoint::saturation_count(),
       sizeof cases / sizeof cases[0]);
  fixedpoint::reset_saturation_count();
  const T in_range[] = {max - T::from_raw(1) + T::from_raw(1), lowest + T::from_raw(1) - T::from_raw(1), big * 3,
                        big * -4, lowest / T(1), max * T(1), lowest * T(1)};
  TEST(named("results at the range ends that fit count nothing", name).c_str(), fixedpoint::saturation_count(), 0u);
  TEST(named("big * -4 reaches lowest() exactly", name).c_str(), in_range[3] == lowest, true);
  fixedpoint::reset_saturation_count();
  TEST(named("a double beyond the range saturates", name).c_str(), T(1e30) == max && T(-1e30) == lowest, true);
  TEST(named("a NaN gives zero", name).c_str(), T(std::nan("")).raw(), 0);
  TEST(named("an out-of-range long long saturates", name).c_str(), T(INT64_MAX) == max, true);
  TEST(named("and each counted", name).c_str(), fixedpoint::saturation_count(), 4u);
  fixedpoint::reset_saturation_count();
}

/// Generic code as ports/ and tracker/ write it: std functions brought in by using-declarations,
/// fixed64's found by argument-dependent lookup.
template <class T>
T generic_expression(T a, T b) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::exp;
  using std::floor;
  using std::log;
  using std::sin;
  using std::sqrt;
  static constexpr T kHalf = T(0.5);
  return sqrt(a * a + b * b) * kHalf + abs(sin(a) * cos(b)) + atan2(b, a) + floor(exp(log(a)));
}

template <int F>
void check_generic_code_and_constant_expressions() {
  using T = fixed64<F>;
  const char* name = type_name<F>();
  const double expected = generic_expression(3.0, 4.0);
  TEST_NEAR(named("generic code gives the double result", name).c_str(), generic_expression(T(3), T(4)), expected,
            8 * std::ldexp(1.0, -F));
  TEST(named("std::max and std::min work", name).c_str(), std::max(T(2), T(3)) == 3 && std::min(T(2), T(3)) == 2,
       true);
  static_assert((T(3) * T(0.5)).raw() == 3 << (F - 1), "* in a constant expression");
  static_assert((T(3) / T(4)).raw() == 3 << (F - 2), "/ in a constant expression");
  static_assert(sqrt(T(9)) == T(3), "sqrt in a constant expression");
  static_assert(cos(T(0)) == T(1), "cos in a constant expression");
  constexpr T kAtCompileTime = sin(T(1.25)) / exp(T(0.75)) + atan2(T(2), T(-3));
  volatile double runtime_input = 1.25;  // keeps the same expression out of constant folding
  const T at_run_time = sin(T(runtime_input)) / exp(T(0.75)) + atan2(T(2), T(-3));
  TEST(named("constant evaluation gives the run-time result", name).c_str(), kAtCompileTime == at_run_time, true);
}

void test_fixed64_generic_code() {
  check_generic_code_and_constant_expressions<16>();
  check_generic_code_and_constant_expressions<23>();
}

void test_fixed64_construction() {
  check_construction_and_conversion<16>();
  check_construction_and_conversion<23>();
}
void test_fixed64_comparisons() {
  check_comparisons_and_operators<16>();
  check_comparisons_and_operators<23>();
}
void test_fixed64_rounding_functions() {
  check_rounding_functions<16>();
  check_rounding_functions<23>();
}
void test_fixed64_numeric_limits() {
  check_numeric_limits<16>();
  check_numeric_limits<23>();
}
void test_fixed64_saturation_counting() {
  check_saturation_counting<16>();
  check_saturation_counting<23>();
}

int defined_count() {
  int n = 0;
#ifdef EDGETRACK_REAL_DOUBLE
  ++n;
#endif
#ifdef EDGETRACK_REAL_FLOAT
  ++n;
#endif
#ifdef EDGETRACK_REAL_S47_16
  ++n;
#endif
#ifdef EDGETRACK_REAL_S40_23
  ++n;
#endif
  return n;
}

void test_real_picks_configured_type() {
  std::printf("EDGETRACK_REAL is %s\n", real_name());
#if defined(EDGETRACK_REAL_DOUBLE)
  const bool right = std::is_same<real, double>::value && std::string(real_name()) == "double";
#elif defined(EDGETRACK_REAL_FLOAT)
  const bool right = std::is_same<real, float>::value && std::string(real_name()) == "float";
#elif defined(EDGETRACK_REAL_S47_16)
  const bool right = std::is_same<real, fixedpoint::s47_16>::value && std::string(real_name()) == "s47_16";
#elif defined(EDGETRACK_REAL_S40_23)
  const bool right = std::is_same<real, fixedpoint::s40_23>::value && std::string(real_name()) == "s40_23";
#endif
  TEST("real is the type EDGETRACK_REAL names", right, true);
  TEST("exactly one EDGETRACK_REAL_* is defined", defined_count(), 1);
  TEST("s47_16 keeps 16 fraction bits", fixedpoint::s47_16::kFractionBits, 16);
  TEST("s40_23 keeps 23 fraction bits", fixedpoint::s40_23::kFractionBits, 23);
}
}  // namespace

TESTMAIN(test_fixed64_construction)
TESTMAIN(test_fixed64_comparisons)
TESTMAIN(test_fixed64_rounding_functions)
TESTMAIN(test_fixed64_numeric_limits)
TESTMAIN(test_fixed64_saturation_counting)
TESTMAIN(test_real_picks_configured_type)
TESTMAIN(test_fixed64_generic_code)
