// SPDX-License-Identifier: BSD-3-Clause
// + - * / and sqrt of fixed64 give the exactly rounded result (at most half an ulp off) over the
// whole 64-bit range, or saturate and count exactly when that result is out of range. The
// reference is exact integer arithmetic (fixed64_test_support.h), since no floating type of the
// ARM build (long double is double there) resolves an ulp of a 63-bit value; where it does, the
// result is also compared with long double.
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>

#include "fixed64_test_support.h"
#include "real/fixed64.h"
#include "testlib/testlib_test.h"

namespace {
using fixed64_test::describe;
using fixed64_test::Exact;
using fixed64_test::Random;
using fixed64_test::type_name;
using fixedpoint::fixed64;

constexpr int kSamples = 100000;

/// Outcome of checking one result against the exact quotient n / d (d > 0), in raw units.
struct Check {
  bool pass = false;
  long double error_ulps = 0;  // |result - n / d|; 0 when saturation was expected
};

/// The result must be n / d rounded to nearest (halves away from zero) and no saturation
/// counted; or, when that rounded value is outside the int64 range, the range end of the right
/// sign with one saturation counted.
Check check_rounded(const Exact& n, const Exact& d, std::int64_t result, std::uint64_t counted) {
  const Exact two(2);
  const Exact twice_n = n * two;
  const bool above = Exact::compare(twice_n, (Exact(INT64_MAX) * two + Exact(1)) * d) >= 0;
  const bool below = Exact::compare(twice_n, (Exact(INT64_MIN) * two - Exact(1)) * d) <= 0;
  if (above || below) return {counted == 1 && result == (above ? INT64_MAX : INT64_MIN), 0};
  const Exact diff = Exact(result) * d - n;
  const long double error = std::fabs(diff.to_long_double() / d.to_long_double());
  // Within half an ulp; exactly half only when rounded away from zero (diff has n's sign).
  const int half = Exact::compare_magnitudes(diff * two, d);
  return {counted == 0 && (half < 0 || (half == 0 && diff.is_negative() == n.is_negative())), error};
}

/// Checks `op` against the exact value `n / d` on kSamples operand pairs from `draw`; prints the
/// worst error and the first failures (operands and result as value and raw hex).
template <int F>
void sweep(const char* name, const char* symbol, Random& random,
           const std::function<void(Random&, std::int64_t&, std::int64_t&)>& draw,
           const std::function<fixed64<F>(fixed64<F>, fixed64<F>)>& op,
           const std::function<void(std::int64_t, std::int64_t, Exact&, Exact&)>& exact) {
  using T = fixed64<F>;
  fixed64_test::WorstError<F> worst;
  int failures = 0, printed = 0, compared_with_long_double = 0, long_double_misses = 0;
  const long double ld_precision = std::ldexp(1.0L, std::numeric_limits<long double>::digits - 2);
  for (int i = 0; i < kSamples; ++i) {
    std::int64_t ra = 0, rb = 0;
    draw(random, ra, rb);
    const T a = T::from_raw(ra), b = T::from_raw(rb);
    const std::uint64_t before = fixedpoint::saturation_count();
    const T r = op(a, b);
    const std::uint64_t counted = fixedpoint::saturation_count() - before;
    Exact n, d;
    exact(ra, rb, n, d);
    const Check c = check_rounded(n, d, r.raw(), counted);
    const auto text = [&] {
      return describe(a) + " " + symbol + " " + describe(b) + " gave " + describe(r) +
             " (saturations counted: " + std::to_string(counted) + ")";
    };
    if (!c.pass) {
      ++failures;
      fixed64_test::report_failure(printed, text());
    }
    if (worst.beaten_by(c.error_ulps)) worst.record(c.error_ulps, text());
    // The same result against long double arithmetic, wherever long double resolves an ulp.
    const long double reference = n.to_long_double() / d.to_long_double();
    if (counted == 0 && std::fabs(reference) < ld_precision) {
      ++compared_with_long_double;
      if (std::fabs(static_cast<long double>(r.raw()) - reference) > 1.0L) ++long_double_misses;
    }
  }
  worst.print(name);
  std::printf("%d of %d results also compared with long double (%d digits)\n", compared_with_long_double, kSamples,
              std::numeric_limits<long double>::digits);
  TEST(("every " + std::string(name) + " of " + type_name<F>() + " is rounded to nearest or saturates and counts")
           .c_str(),
       failures, 0);
  TEST(("every " + std::string(name) + " of " + type_name<F>() + " is within 1 ulp of long double").c_str(),
       long_double_misses, 0);
}

/// The exact product a b / 2^F and quotient a 2^F / b of raw operands as n / d with d > 0.
template <int F>
void exact_product(std::int64_t a, std::int64_t b, Exact& n, Exact& d) {
  n = Exact(a) * Exact(b);
  d = Exact::power_of_two(F);
}
template <int F>
void exact_quotient(std::int64_t a, std::int64_t b, Exact& n, Exact& d) {
  n = Exact(a) * Exact::power_of_two(F);
  d = Exact(b);
  if (b < 0) {
    n = n.negated();
    d = d.negated();
  }
}

template <int F>
void check_add_subtract(std::uint64_t seed) {
  Random random(seed);
  const auto draw = [](Random& rnd, std::int64_t& a, std::int64_t& b) {
    a = rnd.raw();
    b = rnd.raw();
  };
  const auto raw_pair = [](std::int64_t a, std::int64_t b, bool minus, Exact& n, Exact& d) {
    n = minus ? Exact(a) - Exact(b) : Exact(a) + Exact(b);
    d = Exact(1);
  };
  sweep<F>("addition", "+", random, draw, [](fixed64<F> a, fixed64<F> b) { return a + b; },
           [&](std::int64_t a, std::int64_t b, Exact& n, Exact& d) { raw_pair(a, b, false, n, d); });
  sweep<F>("subtraction", "-", random, draw, [](fixed64<F> a, fixed64<F> b) { return a - b; },
           [&](std::int64_t a, std::int64_t b, Exact& n, Exact& d) { raw_pair(a, b, true, n, d); });
}

template <int F>
void check_multiply(std::uint64_t seed) {
  Random random(seed);
  // Half the pairs are independent; the other half have bit lengths whose sum puts the
  // product within a few bits of the range end, where rounding and saturation meet.
  const auto draw = [](Random& rnd, std::int64_t& a, std::int64_t& b) {
    a = rnd.raw();
    if (rnd.below(2) == 0) {
      b = rnd.raw();
      return;
    }
    int length_a = 0;
    for (std::uint64_t m = a < 0 ? 0 - static_cast<std::uint64_t>(a) : static_cast<std::uint64_t>(a); m; m >>= 1)
      ++length_a;
    const int target = 63 + F - length_a + static_cast<int>(rnd.below(5)) - 3;
    b = rnd.raw(target < 0 ? 0 : target > 63 ? 63 : target);
  };
  sweep<F>("multiplication", "*", random, draw, [](fixed64<F> a, fixed64<F> b) { return a * b; },
           exact_product<F>);
}

template <int F>
void check_divide(std::uint64_t seed) {
  Random random(seed);
  const auto draw = [](Random& rnd, std::int64_t& a, std::int64_t& b) {
    a = rnd.raw();
    do b = rnd.raw();
    while (b == 0);
  };
  sweep<F>("division", "/", random, draw, [](fixed64<F> a, fixed64<F> b) { return a / b; },
           exact_quotient<F>);
}

/// A raw value of magnitude `m` with a random sign.
std::int64_t with_random_sign(Random& rnd, std::uint64_t m) {
  const auto v = static_cast<std::int64_t>(m);
  return rnd.below(2) ? -v : v;
}

/// The 32 x 32-bit fast paths of * and their borders: magnitudes of 28 to 34 bits, magnitudes
/// within 2^8 of 2^31 or 2^32 on either side, and exact ties (an odd factor times an odd multiple of
/// 2^(F-1), whose product ends in exactly half an ulp).
template <int F>
void check_multiply_fast_path(std::uint64_t seed) {
  Random random(seed);
  const auto draw = [](Random& rnd, std::int64_t& a, std::int64_t& b) {
    constexpr std::uint64_t kTwo32 = std::uint64_t{1} << 32;
    // A magnitude within 2^8 of 2^31 or 2^32.
    const auto near_two32 = [&rnd] { return (kTwo32 >> rnd.below(2)) - 256 + rnd.below(512); };
    switch (rnd.below(4)) {
      case 0:
        a = rnd.raw(28 + static_cast<int>(rnd.below(7)));
        b = rnd.raw(28 + static_cast<int>(rnd.below(7)));
        break;
      case 1:
        a = with_random_sign(rnd, near_two32());
        b = rnd.below(2) ? with_random_sign(rnd, near_two32()) : rnd.raw(33);
        break;
      case 2: {
        a = with_random_sign(rnd, (rnd.next() >> 32) | 1);
        const std::uint64_t odd = ((rnd.next() >> (64 - (32 - F))) | 1);  // odd * 2^(F-1) < 2^32
        b = with_random_sign(rnd, odd << (F - 1));
        break;
      }
      default:
        a = rnd.raw(32);
        b = rnd.raw(32);
    }
  };
  sweep<F>("multiplication near the 32-bit fast path", "*", random, draw,
           [](fixed64<F> a, fixed64<F> b) { return a * b; },
           exact_product<F>);
}

/// The 64 / 32-bit fast path of / and its borders: divisors within 2^8 of 2^31 and 2^32 on
/// either side, powers of two and small whole numbers; dividends below, at and just above
/// 2^(64-F) (where |a| 2^F leaves 64 bits); exact ties (quotients ending in half an ulp).
template <int F>
void check_divide_fast_path(std::uint64_t seed) {
  Random random(seed);
  const auto draw = [](Random& rnd, std::int64_t& a, std::int64_t& b) {
    constexpr std::uint64_t kLimit = std::uint64_t{1} << (64 - F);
    switch (rnd.below(5)) {
      case 0:
        b = with_random_sign(rnd, (std::uint64_t{1} << (31 + rnd.below(2))) - 256 + rnd.below(512));
        a = rnd.raw(64 - F);
        break;
      case 1:
        b = with_random_sign(rnd, std::uint64_t{1} << rnd.below(40));
        a = rnd.raw(64 - F);
        break;
      case 2:
        b = with_random_sign(rnd, 1 + rnd.below(std::uint64_t{1} << (F + 10)));
        a = with_random_sign(rnd, kLimit - 256 + rnd.below(512));
        break;
      case 3: {
        // b = 2^(F+1) c and a = (2q + 1) c give a / b = (2q + 1) / 2^(F+1): a tie in raw units.
        const std::uint64_t c = 1 + rnd.below(std::uint64_t{1} << (31 - F));
        b = with_random_sign(rnd, c << (F + 1));
        a = with_random_sign(rnd, (2 * rnd.below(std::uint64_t{1} << 20) + 1) * c);
        break;
      }
      default:
        a = rnd.raw(64 - F);
        do b = rnd.raw(33);
        while (b == 0);
    }
  };
  sweep<F>("division near the 64 / 32-bit fast path", "/", random, draw,
           [](fixed64<F> a, fixed64<F> b) { return a / b; },
           exact_quotient<F>);
  // fixed64_divisor gives a / b bit for bit, on and off the fast path, saturations counted alike.
  int failures = 0, printed = 0;
  for (int i = 0; i < kSamples / 4; ++i) {
    std::int64_t a = 0, b = 0;
    draw(random, a, b);
    if (i % 7 == 0) b = random.raw(63);  // past the fast path
    if (i % 11 == 0) b = 0;
    const fixed64<F> x = fixed64<F>::from_raw(a), y = fixed64<F>::from_raw(b);
    std::uint64_t before = fixedpoint::saturation_count();
    const fixed64<F> expected = x / y;
    const std::uint64_t expected_count = fixedpoint::saturation_count() - before;
    before = fixedpoint::saturation_count();
    const fixed64<F> got = fixedpoint::fixed64_divisor<F>(y).divide(x);
    if (got.raw() != expected.raw() || fixedpoint::saturation_count() - before != expected_count) {
      ++failures;
      fixed64_test::report_failure(printed, describe(x) + " over the divisor " + describe(y) + " gave " + describe(got));
    }
  }
  TEST((std::string("fixed64_divisor of ") + type_name<F>() + " divides as / does, bit for bit").c_str(), failures, 0);
}

/// sqrt(x) is correctly rounded iff (2r - 1)^2 <= 4 raw 2^F <= (2r + 1)^2 (no ties: the middle
/// is never an integer square).
template <int F>
void check_sqrt(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  fixed64_test::WorstError<F> worst;
  int failures = 0, printed = 0;
  for (int i = 0; i < kSamples; ++i) {
    std::int64_t raw = random.raw();
    if (raw < 0) raw = raw == INT64_MIN ? INT64_MAX : -raw;
    const T x = T::from_raw(raw);
    const std::uint64_t before = fixedpoint::saturation_count();
    const T r = sqrt(x);
    const std::uint64_t counted = fixedpoint::saturation_count() - before;
    const Exact four_n = Exact(raw) * Exact::power_of_two(F + 2);
    const Exact low = Exact(2 * r.raw() - 1), high = Exact(2 * r.raw() + 1);
    const bool pass = counted == 0 && r.raw() >= 0 && (r.raw() == 0 || Exact::compare(low * low, four_n) <= 0) &&
                      Exact::compare(four_n, high * high) <= 0;
    const long double root = std::sqrt(static_cast<long double>(raw) * std::ldexp(1.0L, F));
    const long double error = std::fabs(static_cast<long double>(r.raw()) - root);
    const auto text = [&] { return "sqrt(" + describe(x) + ") gave " + describe(r); };
    if (!pass) {
      ++failures;
      fixed64_test::report_failure(printed, text());
    }
    if (worst.beaten_by(error)) worst.record(error, text());
  }
  worst.print("sqrt");
  TEST((std::string("every sqrt of ") + type_name<F>() + " is correctly rounded").c_str(), failures, 0);
  const std::uint64_t before = fixedpoint::saturation_count();
  TEST((std::string("sqrt of a negative ") + type_name<F>() + " gives 0").c_str(), sqrt(T(-4)), T(0));
  TEST("and counts one saturation", fixedpoint::saturation_count() - before, 1u);
  TEST("sqrt(0) is 0", sqrt(T(0)), T(0));
  TEST("sqrt(ulp) rounds to the nearest representable root",
       sqrt(T::from_raw(1)).raw(), static_cast<std::int64_t>(std::llround(std::ldexp(1.0, F / 2) *
                                                                          (F % 2 ? std::sqrt(2.0) : 1.0))));
  TEST("sqrt(max) does not saturate", sqrt(std::numeric_limits<T>::max()) > T(0), true);
}

/// euclidean_norm(n, x): correctly rounded (as sqrt above) while the sum of the raw squares is
/// below 2^64; above, within 2^-30 relative of the exact root; saturates and counts past max().
template <int F>
void check_euclidean_norm(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  int rounding_failures = 0, relative_failures = 0, printed = 0;
  T x[80];
  for (int i = 0; i < kSamples / 20; ++i) {
    const int n = 1 + static_cast<int>(random.below(80));
    const bool small = i % 2 == 0;  // half the vectors keep the sum below 2^64
    Exact sum(0);
    for (int k = 0; k < n; ++k) {
      x[k] = T::from_raw(small ? random.raw(28) : random.raw(56));
      sum = sum + Exact(x[k].raw()) * Exact(x[k].raw());
    }
    const std::uint64_t before = fixedpoint::saturation_count();
    const T r = euclidean_norm(n, x);
    const bool counted = fixedpoint::saturation_count() != before;
    const auto text = [&] { return "norm of " + std::to_string(n) + " values gave " + describe(r); };
    if (Exact::compare(sum, Exact::power_of_two(64)) < 0) {
      const Exact four_sum = sum * Exact(4);
      const Exact low = Exact(2 * r.raw() - 1), high = Exact(2 * r.raw() + 1);
      if (counted || (r.raw() != 0 && Exact::compare(low * low, four_sum) > 0) ||
          Exact::compare(four_sum, high * high) > 0) {
        ++rounding_failures;
        fixed64_test::report_failure(printed, text());
      }
    } else {
      const long double root = std::sqrt(sum.to_long_double());
      if (counted || std::fabs(static_cast<long double>(r.raw()) - root) > root * std::ldexp(1.0L, -30)) {
        ++relative_failures;
        fixed64_test::report_failure(printed, text());
      }
    }
  }
  TEST((std::string("euclidean_norm of ") + type_name<F>() + " is correctly rounded below 2^64 raw squared").c_str(),
       rounding_failures, 0);
  TEST((std::string("euclidean_norm of ") + type_name<F>() + " is within 2^-30 relative above").c_str(),
       relative_failures, 0);
  const T big[2] = {std::numeric_limits<T>::max(), std::numeric_limits<T>::max()};
  const std::uint64_t before = fixedpoint::saturation_count();
  TEST("the norm of two max() saturates to max()", euclidean_norm(2, big), std::numeric_limits<T>::max());
  TEST("and counts one saturation", fixedpoint::saturation_count() - before, 1u);
  const T three_four[2] = {T(3), T(-4)};
  TEST("the norm of (3, -4) is 5", euclidean_norm(2, three_four), T(5));
  TEST("the norm of nothing is 0", euclidean_norm(0, x), T(0));
}

/// dot_product(n, a, b) is the exact sum of the products rounded once (check_rounded), or
/// saturates and counts when that is out of range.
template <int F>
void check_dot_product(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  int failures = 0, printed = 0;
  T a[80], b[80];
  for (int i = 0; i < kSamples / 20; ++i) {
    const int n = 1 + static_cast<int>(random.below(80));
    // Past, near and within the fast path, and (every fourth) each element's own size, so that
    // int32 products and 128-bit ones alternate in one sum.
    const int widths[3] = {62, 40, 30};
    const int bits = widths[i % 3];
    Exact sum(0);
    for (int k = 0; k < n; ++k) {
      const int width = i % 4 == 3 ? widths[random.below(3)] : bits;
      a[k] = T::from_raw(random.raw(width));
      b[k] = T::from_raw(random.raw(width));
      sum = sum + Exact(a[k].raw()) * Exact(b[k].raw());
    }
    const std::uint64_t before = fixedpoint::saturation_count();
    const T r = dot_product(n, a, b);
    const std::uint64_t counted = fixedpoint::saturation_count() - before;
    if (!check_rounded(sum, Exact::power_of_two(F), r.raw(), counted).pass) {
      ++failures;
      fixed64_test::report_failure(printed, "dot product of " + std::to_string(n) + " pairs gave " + describe(r));
    }
  }
  TEST((std::string("dot_product of ") + type_name<F>() + " rounds the exact sum once, or saturates").c_str(),
       failures, 0);
  const T half_ulp[2] = {T::from_raw(1), T::from_raw(1)}, half[2] = {T(0.5), T(0.5)};
  TEST("two products of half an ulp each sum to one ulp", dot_product(2, half_ulp, half).raw(), 1);
}

/// The few-pairs dot_product (two or three pairs in variables) gives dot_product(n, a, b) bit
/// for bit, saturations counted alike, with operands within, near and past int32 and sums near
/// 2^63 (where its 64-bit sum would overflow).
template <int F>
void check_few_pairs_dot_product(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  int failures = 0, printed = 0;
  const int widths[4] = {31, 32, 40, 62};
  for (int i = 0; i < kSamples / 4; ++i) {
    T a[3], b[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = T::from_raw(random.raw(widths[random.below(4)]));
      b[k] = T::from_raw(random.raw(widths[random.below(4)]));
    }
    if (i % 5 == 0)  // int32 extremes: products near 2^62 whose sum passes 2^63
      for (int k = 0; k < 3; ++k) a[k] = b[k] = T::from_raw(random.below(2) ? -2147483647 - 1 : 2147483647);
    std::uint64_t before = fixedpoint::saturation_count();
    const T two = dot_product(2, a, b), three = dot_product(3, a, b);
    const std::uint64_t expected_count = fixedpoint::saturation_count() - before;
    before = fixedpoint::saturation_count();
    const T few_two = dot_product(a[0], b[0], a[1], b[1]), few_three = dot_product(a[0], b[0], a[1], b[1], a[2], b[2]);
    if (few_two.raw() != two.raw() || few_three.raw() != three.raw() ||
        fixedpoint::saturation_count() - before != expected_count) {
      ++failures;
      fixed64_test::report_failure(printed, "few-pairs dot product of " + describe(a[0]) + " ... gave " +
                                                describe(few_three) + " for " + describe(three));
    }
  }
  TEST((std::string("the few-pairs dot_product of ") + type_name<F>() + " is dot_product's, bit for bit").c_str(),
       failures, 0);
}

/// add_multiple(n, s, x, y) gives y[i] + s * x[i] bit for bit, saturations counted alike, for
/// scales and elements within, near and past the fast paths.
template <int F>
void check_add_multiple(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  int failures = 0, printed = 0;
  const int widths[3] = {62, 40, 30};
  T x[40], y[40], expected[40];
  for (int i = 0; i < kSamples / 20; ++i) {
    const int n = 1 + static_cast<int>(random.below(40));
    const T s = T::from_raw(random.raw(widths[i % 3]));
    for (int k = 0; k < n; ++k) {
      x[k] = T::from_raw(random.raw(widths[random.below(3)]));
      y[k] = T::from_raw(random.raw(widths[random.below(3)]));
    }
    std::uint64_t before = fixedpoint::saturation_count();
    for (int k = 0; k < n; ++k) expected[k] = y[k] + s * x[k];
    const std::uint64_t expected_count = fixedpoint::saturation_count() - before;
    before = fixedpoint::saturation_count();
    add_multiple(n, s, x, y);
    bool same = fixedpoint::saturation_count() - before == expected_count;
    for (int k = 0; k < n; ++k) same = same && y[k].raw() == expected[k].raw();
    if (!same) {
      ++failures;
      fixed64_test::report_failure(printed, "add_multiple of " + std::to_string(n) + " by " + describe(s));
    }
  }
  TEST((std::string("add_multiple of ") + type_name<F>() + " is y + s * x, bit for bit").c_str(), failures, 0);
}

void test_fixed64_norm_and_dot_product() {
  check_euclidean_norm<16>(0x5eed0011);
  check_euclidean_norm<23>(0x5eed0012);
  check_dot_product<16>(0x5eed0013);
  check_dot_product<23>(0x5eed0014);
  check_add_multiple<16>(0x5eed0015);
  check_add_multiple<23>(0x5eed0016);
  check_few_pairs_dot_product<16>(0x5eed0017);
  check_few_pairs_dot_product<23>(0x5eed0018);
}

void test_fixed64_add_subtract() {
  check_add_subtract<16>(0x5eed0001);
  check_add_subtract<23>(0x5eed0002);
}
void test_fixed64_multiply() {
  check_multiply<16>(0x5eed0003);
  check_multiply<23>(0x5eed0004);
}
void test_fixed64_divide() {
  check_divide<16>(0x5eed0005);
  check_divide<23>(0x5eed0006);
}
void test_fixed64_multiply_fast_path() {
  check_multiply_fast_path<16>(0x5eed0009);
  check_multiply_fast_path<23>(0x5eed000a);
  using T = fixed64<23>;
  static_assert((T(-3) * T(1.5)).raw() == -9 * (std::int64_t{1} << 22), "int32 * in a constant expression");
  static_assert((T(300) * T(-1.5)).raw() == -450 * (std::int64_t{1} << 23), "32-bit * in a constant expression");
  static_assert((T(100000) * T(-3)).raw() == -300000 * (std::int64_t{1} << 23), "128-bit * in a constant expression");
}
void test_fixed64_divide_fast_path() {
  check_divide_fast_path<16>(0x5eed000b);
  check_divide_fast_path<23>(0x5eed000c);
  using T = fixed64<23>;
  static_assert((T(-300) / T(8)).raw() == -300 * (std::int64_t{1} << 20), "fast / in a constant expression");
  static_assert((T(1000000) / T(-4)).raw() == -250000 * (std::int64_t{1} << 23), "128-bit / in a constant expression");
}
/// An unsigned 64-bit value as an Exact.
Exact unsigned_exact(std::uint64_t x) {
  return Exact(static_cast<std::int64_t>(x >> 1)) * Exact(2) + Exact(static_cast<std::int64_t>(x & 1));
}

/// The reciprocal behind every division: for normalised divisors (top bit set), 2^32 + v never
/// exceeds 2^64 / d and is at most 4 below it; 64 / 32 and 128 / 64-bit quotients and
/// remainders are exact.
void test_wide_uint_reciprocal_and_division() {
  using fixedpoint::detail::divide;
  using fixedpoint::detail::reciprocal;
  Random rnd(0x5eed000d);
  int reciprocal_failures = 0, printed = 0;
  const Exact two64 = Exact::power_of_two(64);
  for (int i = 0; i < kSamples; ++i) {
    std::uint32_t d = static_cast<std::uint32_t>(rnd.next() >> 32) | 0x80000000u;
    if (i < 256) d = 0x80000000u + static_cast<std::uint32_t>(i);  // both ends of the range first
    if (i >= 256 && i < 512) d = 0xffffffffu - static_cast<std::uint32_t>(i - 256);
    const std::uint32_t v = reciprocal(d);
    const Exact x = Exact(static_cast<std::int64_t>((std::uint64_t{1} << 32) + v));
    const Exact dd = Exact(static_cast<std::int64_t>(d));
    if (Exact::compare(x * dd, two64) > 0 || Exact::compare((x + Exact(5)) * dd, two64) <= 0) {
      ++reciprocal_failures;
      fixed64_test::report_failure(printed, "reciprocal(" + std::to_string(d) + ") gave " + std::to_string(v));
    }
  }
  TEST("2^32 + reciprocal(d) lies in (2^64 / d - 5, 2^64 / d] for sampled normalised d", reciprocal_failures, 0);
  int division_failures = 0;
  for (int i = 0; i < kSamples; ++i) {
    const std::uint64_t n = rnd.next() >> rnd.below(64);
    std::uint32_t d = static_cast<std::uint32_t>(rnd.next() >> (32 + rnd.below(32)));
    if (d == 0) d = 1;
    const auto qr = divide(n, d);
    const bool exact = qr.remainder < d && Exact::compare(unsigned_exact(qr.quotient) * unsigned_exact(d) +
                                                              unsigned_exact(qr.remainder),
                                                          unsigned_exact(n)) == 0;
    if (!exact) {
      ++division_failures;
      fixed64_test::report_failure(printed, std::to_string(n) + " / " + std::to_string(d) + " gave " +
                                                std::to_string(qr.quotient) + " remainder " +
                                                std::to_string(qr.remainder));
    }
  }
  TEST("64 / 32-bit divide gives n = q d + r with r < d", division_failures, 0);
  // 128 / 64 bits, half of them with a dividend just below d 2^64, where the top dividend digit
  // equals the top divisor digit and the digit estimate starts at 2^32 - 1.
  int wide_failures = 0;
  for (int i = 0; i < kSamples; ++i) {
    std::uint64_t d = rnd.next() >> rnd.below(64);
    if (d == 0) d = 1;
    fixedpoint::detail::Uint128 n{rnd.next() % d, rnd.next()};
    if (i % 2 == 0) n.hi = d - 1 - rnd.below(d < (std::uint64_t{1} << 32) ? d : std::uint64_t{1} << 32);
    const auto qr = divide(n, d);
    const Exact exact_n = unsigned_exact(n.hi) * Exact::power_of_two(64) + unsigned_exact(n.lo);
    const Exact recombined = unsigned_exact(qr.quotient) * unsigned_exact(d) + unsigned_exact(qr.remainder);
    if (!(qr.remainder < d && Exact::compare(recombined, exact_n) == 0)) {
      ++wide_failures;
      fixed64_test::report_failure(printed, "(" + std::to_string(n.hi) + " 2^64 + " + std::to_string(n.lo) + ") / " +
                                                std::to_string(d) + " gave " + std::to_string(qr.quotient));
    }
  }
  TEST("128 / 64-bit divide gives n = q d + r with r < d", wide_failures, 0);
}
/// The 64-bit integer square root (Newton estimate, then corrected) is exact: root^2 <= n <
/// (root + 1)^2 and the remainder is n - root^2, on seeded n of every length, on perfect squares
/// and their neighbours up to (2^32 - 1)^2, and next to every power of two.
void test_wide_uint_square_root() {
  using fixedpoint::detail::square_root;
  Random rnd(0x5eed000e);
  int failures = 0, printed = 0;
  const auto check = [&](std::uint64_t n) {
    const auto s = square_root(n);
    const Exact root = unsigned_exact(s.root), next = unsigned_exact(s.root + 1), exact_n = unsigned_exact(n);
    const bool exact = s.root <= 0xffffffffu && s.remainder.hi == 0 && Exact::compare(root * root, exact_n) <= 0 &&
                       Exact::compare(next * next, exact_n) > 0 &&
                       Exact::compare(root * root + unsigned_exact(s.remainder.lo), exact_n) == 0;
    if (!exact) {
      ++failures;
      fixed64_test::report_failure(printed, "square_root(" + std::to_string(n) + ") gave " + std::to_string(s.root));
    }
  };
  for (int i = 0; i < kSamples; ++i) check(rnd.next() >> rnd.below(64));
  for (int i = 0; i < 2000; ++i) {
    const std::uint64_t r = i < 1000 ? 0xffffffffu - static_cast<std::uint64_t>(i) : rnd.next() >> 32;
    const std::uint64_t square = r * r;
    check(square);
    check(square - 1);
    check(square + 1);
    check(square + 2 * r);  // the largest n with this root
  }
  for (int k = 0; k < 64; ++k)
    for (int d = -2; d <= 2; ++d) check((std::uint64_t{1} << k) + static_cast<std::uint64_t>(d));
  TEST("64-bit square_root gives root^2 <= n < (root + 1)^2 and the remainder", failures, 0);
}
void test_fixed64_sqrt() {
  check_sqrt<16>(0x5eed0007);
  check_sqrt<23>(0x5eed0008);
}
}  // namespace

TESTMAIN(test_fixed64_add_subtract)
TESTMAIN(test_fixed64_multiply)
TESTMAIN(test_fixed64_divide)
TESTMAIN(test_fixed64_sqrt)
TESTMAIN(test_fixed64_norm_and_dot_product)
TESTMAIN(test_fixed64_multiply_fast_path)
TESTMAIN(test_fixed64_divide_fast_path)
TESTMAIN(test_wide_uint_reciprocal_and_division)
TESTMAIN(test_wide_uint_square_root)
