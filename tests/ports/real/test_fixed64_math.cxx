// SPDX-License-Identifier: BSD-3-Clause
// sin, cos, tan, atan, atan2, asin, acos, exp and log of fixed64 stay within their documented
// error bounds (fixed64_math.h) on 10^5 seeded arguments per function and type, over the whole
// range, against long double (double under QEMU, where arguments beyond 2^53 ulps are split
// into two exact parts for sin and cos); domain errors and overflows saturate and count.
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
using fixed64_test::Random;
using fixed64_test::type_name;
using fixedpoint::fixed64;

constexpr int kSamples = 100000;
constexpr double kPi = 3.14159265358979323846;
/// One unit in the last place of long double, relative: the reference's own rounding.
const long double kReferenceEpsilon = std::numeric_limits<long double>::epsilon();

/// Value of a raw fixed64 as long double (exact on x86-64; rounded to 53 bits under QEMU).
template <int F>
long double value_of(std::int64_t raw) {
  return std::ldexp(static_cast<long double>(raw), -F);
}

/// sin and cos of raw / 2^F, exact argument: raw = a 2^32 + b splits it into two parts that
/// any binary floating type holds exactly, joined by the angle-sum formulas.
template <int F>
void reference_sin_cos(std::int64_t raw, long double& s, long double& c) {
  const std::int64_t high = raw >> 32;  // floor
  const std::int64_t low = raw - high * (std::int64_t{1} << 32);
  const long double a = std::ldexp(static_cast<long double>(high), 32 - F);
  const long double b = std::ldexp(static_cast<long double>(low), -F);
  if (high == 0 || high == -1) {
    s = std::sin(a + b);
    c = std::cos(a + b);
    return;
  }
  const long double sa = std::sin(a), ca = std::cos(a), sb = std::sin(b), cb = std::cos(b);
  s = sa * cb + ca * sb;
  c = ca * cb - sa * sb;
}

/// Tallies one function's sweep: failures, the worst error, and the first failures printed.
template <int F>
class Sweep {
 public:
  Sweep(const char* function, const char* bound) : function_(function), bound_(bound) {}

  /// Checks `got` against the exact value `reference` with `tolerance` ulps. A result that
  /// counted a saturation must be a range end, with the reference beyond it (within tolerance).
  void check(fixed64<F> got, long double reference, long double tolerance, std::uint64_t counted,
             const std::function<std::string()>& arguments) {
    const long double target = std::ldexp(reference, F);
    const long double error = std::fabs(static_cast<long double>(got.raw()) - target);
    bool pass;
    if (counted != 0) {
      pass = counted == 1 && ((got.raw() == INT64_MAX && target >= 9223372036854775807.5L - tolerance) ||
                              (got.raw() == INT64_MIN && target <= -9223372036854775808.5L + tolerance));
    } else {
      pass = error <= tolerance;
      if (worst_.beaten_by(error)) worst_.record(error, arguments() + " gave " + describe(got));
    }
    if (!pass) {
      ++failures_;
      fixed64_test::report_failure(printed_, function_ + std::string(" of ") + arguments() + " gave " +
                                                 describe(got) + ", expected " + std::to_string(double(reference)) +
                                                 " (saturations counted: " + std::to_string(counted) + ")");
    }
  }
  void finish() const {
    worst_.print(function_);
    TEST((std::string(function_) + " of " + type_name<F>() + " is within " + bound_).c_str(), failures_, 0);
  }

 private:
  const char* function_;
  const char* bound_;
  fixed64_test::WorstError<F> worst_;
  int failures_ = 0;
  int printed_ = 0;
};

/// Runs `function` and reports how many saturations it counted.
template <class Result>
Result counting(std::uint64_t& counted, const std::function<Result()>& function) {
  const std::uint64_t before = fixedpoint::saturation_count();
  const Result r = function();
  counted = fixedpoint::saturation_count() - before;
  return r;
}

template <int F>
void check_sin_cos(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  Sweep<F> sin_sweep("sin", "1 ulp"), cos_sweep("cos", "1 ulp");
  for (int i = 0; i < kSamples; ++i) {
    const T x = T::from_raw(random.raw());
    long double s = 0, c = 0;
    reference_sin_cos<F>(x.raw(), s, c);
    const long double tolerance = 1 + std::ldexp(2 * kReferenceEpsilon, F);
    std::uint64_t counted = 0;
    const T got_sin = counting<T>(counted, [x] { return sin(x); });
    sin_sweep.check(got_sin, s, tolerance, counted, [x] { return describe(x); });
    const T got_cos = counting<T>(counted, [x] { return cos(x); });
    cos_sweep.check(got_cos, c, tolerance, counted, [x] { return describe(x); });
  }
  sin_sweep.finish();
  cos_sweep.finish();
  TEST_NEAR((std::string("sin(pi/6) is 1/2 for ") + type_name<F>()).c_str(), sin(T(kPi / 6)), 0.5, std::ldexp(1.0, -F));
  TEST((std::string("cos(0) is exactly 1 for ") + type_name<F>()).c_str(), cos(T(0)) == T(1), true);
  TEST((std::string("sin(0) is exactly 0 for ") + type_name<F>()).c_str(), sin(T(0)) == T(0), true);
}

/// tan: the angle's own rounding is magnified by the slope 1 + tan^2 near the poles; the bound
/// is 1 ulp + (1 + tan^2) 2^(F-58) ulp, checked on |x| <= 2^20.
template <int F>
void check_tan(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  Sweep<F> sweep("tan", "1 ulp + (1 + tan^2) 2^(F-58) ulp");
  for (int i = 0; i < kSamples; ++i) {
    const T x = T::from_raw(random.raw(20 + F));
    long double s = 0, c = 0;
    reference_sin_cos<F>(x.raw(), s, c);
    const long double t = s / c;
    const long double tolerance = 1 + (1 + t * t) * std::ldexp(1.0L, F - 58) + std::ldexp(4 * kReferenceEpsilon * std::fabs(t) * (1 + t * t), F);
    std::uint64_t counted = 0;
    const T got = counting<T>(counted, [x] { return tan(x); });
    sweep.check(got, t, tolerance, counted, [x] { return describe(x); });
  }
  sweep.finish();
  TEST_NEAR((std::string("tan(pi/4) is 1 for ") + type_name<F>()).c_str(), tan(T(kPi / 4)), 1.0, std::ldexp(1.0, -F));
}

template <int F>
void check_atan_atan2(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  Sweep<F> atan_sweep("atan", "1 ulp"), atan2_sweep("atan2", "1 ulp");
  const long double tolerance = 1 + std::ldexp(8 * kReferenceEpsilon, F);
  for (int i = 0; i < kSamples; ++i) {
    const T x = T::from_raw(random.raw());
    std::uint64_t counted = 0;
    const T got = counting<T>(counted, [x] { return atan(x); });
    atan_sweep.check(got, std::atan(value_of<F>(x.raw())), tolerance, counted, [x] { return describe(x); });
    const T y = T::from_raw(random.raw()), z = T::from_raw(random.raw());
    const T got2 = counting<T>(counted, [y, z] { return atan2(y, z); });
    atan2_sweep.check(got2, std::atan2(value_of<F>(y.raw()), value_of<F>(z.raw())), tolerance, counted,
                      [y, z] { return describe(y) + ", " + describe(z); });
  }
  atan_sweep.finish();
  atan2_sweep.finish();
  const T pi(kPi);
  const std::string name = type_name<F>();
  TEST_NEAR(("atan2(0, -1) is pi for " + name).c_str(), atan2(T(0), T(-1)), pi, std::ldexp(1.0, -F));
  TEST(("atan2(0, 0) is 0 for " + name).c_str(), atan2(T(0), T(0)) == T(0), true);
  TEST_NEAR(("atan2(-1, 0) is -pi/2 for " + name).c_str(), atan2(T(-1), T(0)), -kPi / 2, std::ldexp(1.0, -F));
  TEST_NEAR(("atan2(lowest, lowest) is -3pi/4 for " + name).c_str(),
            atan2(std::numeric_limits<T>::lowest(), std::numeric_limits<T>::lowest()), -3 * kPi / 4,
            std::ldexp(1.0, -F));
}

template <int F>
void check_asin_acos(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  Sweep<F> asin_sweep("asin", "1 ulp"), acos_sweep("acos", "1 ulp");
  const long double tolerance = 1 + std::ldexp(8 * kReferenceEpsilon, F);
  constexpr std::int64_t kOne = std::int64_t{1} << F;
  for (int i = 0; i < kSamples; ++i) {
    // One argument in four within 1024 ulps of +-1, where both functions are steepest.
    std::int64_t raw = random.uniform_raw(-kOne, kOne);
    if (random.below(4) == 0) {
      const auto offset = static_cast<std::int64_t>(random.below(1024));
      raw = random.below(2) ? kOne - offset : offset - kOne;
    }
    const T x = T::from_raw(raw);
    std::uint64_t counted = 0;
    const T got_asin = counting<T>(counted, [x] { return asin(x); });
    asin_sweep.check(got_asin, std::asin(value_of<F>(raw)), tolerance, counted, [x] { return describe(x); });
    const T got_acos = counting<T>(counted, [x] { return acos(x); });
    acos_sweep.check(got_acos, std::acos(value_of<F>(raw)), tolerance, counted, [x] { return describe(x); });
  }
  asin_sweep.finish();
  acos_sweep.finish();
  const std::string name = type_name<F>();
  const std::uint64_t before = fixedpoint::saturation_count();
  TEST_NEAR(("asin(2) saturates to pi/2 for " + name).c_str(), asin(T(2)), kPi / 2, std::ldexp(1.0, -F));
  TEST_NEAR(("acos(-2) saturates to pi for " + name).c_str(), acos(T(-2)), kPi, std::ldexp(1.0, -F));
  TEST(("and both count a saturation for " + name).c_str(), fixedpoint::saturation_count() - before, 2u);
  TEST(("acos(1) is exactly 0 for " + name).c_str(), acos(T(1)) == T(0), true);
}

/// exp: within 1 ulp + 2^-60 of the result (relative; it matters only in the top binades),
/// plus the reference's own rounding.
template <int F>
void check_exp_log(std::uint64_t seed) {
  using T = fixed64<F>;
  Random random(seed);
  Sweep<F> exp_sweep("exp", "1 ulp + 2^-60 exp(x)"), log_sweep("log", "1 ulp");
  // exp is swept over [-(F + 3) ln 2, 45]: from below half an ulp to past the range end.
  const std::int64_t low = -static_cast<std::int64_t>((F + 3) * 0.6931471805599453 * (1 << F));
  const std::int64_t high = std::int64_t{45} << F;
  for (int i = 0; i < kSamples; ++i) {
    const T x = T::from_raw(random.uniform_raw(low, high));
    const long double e = std::exp(value_of<F>(x.raw()));
    const long double exp_tolerance = 1 + std::ldexp(e, F) * (std::ldexp(1.0L, -60) + 2 * kReferenceEpsilon);
    std::uint64_t counted = 0;
    const T got_exp = counting<T>(counted, [x] { return exp(x); });
    exp_sweep.check(got_exp, e, exp_tolerance, counted, [x] { return describe(x); });

    std::int64_t raw = random.raw();
    raw = raw == INT64_MIN ? INT64_MAX : raw < 0 ? -raw : raw == 0 ? 1 : raw;
    const T y = T::from_raw(raw);
    const T got_log = counting<T>(counted, [y] { return log(y); });
    log_sweep.check(got_log, std::log(value_of<F>(raw)), 1 + std::ldexp(64 * kReferenceEpsilon, F), counted,
                    [y] { return describe(y); });
  }
  exp_sweep.finish();
  log_sweep.finish();
  const std::string name = type_name<F>();
  TEST(("exp(0) is exactly 1 for " + name).c_str(), exp(T(0)) == T(1), true);
  TEST(("log(1) is exactly 0 for " + name).c_str(), log(T(1)) == T(0), true);
  TEST(("exp(lowest) is 0 for " + name).c_str(), exp(std::numeric_limits<T>::lowest()) == T(0), true);
  std::uint64_t before = fixedpoint::saturation_count();
  TEST(("exp(max) saturates to max for " + name).c_str(),
       exp(std::numeric_limits<T>::max()) == std::numeric_limits<T>::max(), true);
  TEST(("and counts one saturation for " + name).c_str(), fixedpoint::saturation_count() - before, 1u);
  before = fixedpoint::saturation_count();
  TEST(("log(0) and log(-1) give lowest for " + name).c_str(),
       log(T(0)) == std::numeric_limits<T>::lowest() && log(T(-1)) == std::numeric_limits<T>::lowest(), true);
  TEST(("and count one saturation each for " + name).c_str(), fixedpoint::saturation_count() - before, 2u);
  TEST_NEAR(("log(exp(3)) is 3 for " + name).c_str(), log(exp(T(3))), 3.0, 2 * std::ldexp(1.0, -F));
}

void test_fixed64_sin_cos() {
  check_sin_cos<16>(0x5eed0101);
  check_sin_cos<23>(0x5eed0102);
}
void test_fixed64_tan() {
  check_tan<16>(0x5eed0103);
  check_tan<23>(0x5eed0104);
}
void test_fixed64_atan_atan2() {
  check_atan_atan2<16>(0x5eed0105);
  check_atan_atan2<23>(0x5eed0106);
}
void test_fixed64_asin_acos() {
  check_asin_acos<16>(0x5eed0107);
  check_asin_acos<23>(0x5eed0108);
}
void test_fixed64_exp_log() {
  check_exp_log<16>(0x5eed0109);
  check_exp_log<23>(0x5eed010a);
}
}  // namespace

TESTMAIN(test_fixed64_sin_cos)
TESTMAIN(test_fixed64_tan)
TESTMAIN(test_fixed64_atan_atan2)
TESTMAIN(test_fixed64_asin_acos)
TESTMAIN(test_fixed64_exp_log)
