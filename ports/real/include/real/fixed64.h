// SPDX-License-Identifier: BSD-3-Clause
/// The 64-bit signed fixed-point type of the paper's section 3.3 (S47.16, then S40.23), written
/// after fpm's include/fpm/fixed.hpp: a class template over the fraction bits, free operators,
/// rounded * and /, and std::numeric_limits. Unlike fpm it needs no wider built-in type (see
/// wide_uint.h), and overflow saturates and is counted instead of wrapping.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <type_traits>

#include "real/wide_uint.h"

/// fixed64's +, -, *, comparisons and conversions, forced inline where FIXEDPOINT_FORCE_INLINE is
/// defined: the sources built for size (-Os) whose loops are a frame's (the bare-metal tree,
/// toolchains/mcu/hot_sources.cmake), where GCC would otherwise call each of them.
#if defined(FIXEDPOINT_FORCE_INLINE)
#define FIXED64_INLINE __attribute__((always_inline))
#else
#define FIXED64_INLINE
#endif
/// Where a source is built for size (-Os defines __OPTIMIZE_SIZE__), the out-of-line division and
/// the small vector operations of a frame (edgetrack/geometry.h) inline what they call: each
/// stays one function in the image, whichever source's copy the linker keeps, instead of a chain
/// of calls. Builds for speed inline by their own choice, unchanged.
#if defined(__OPTIMIZE_SIZE__)
#define FIXED64_FLATTEN __attribute__((flatten))
#else
#define FIXED64_FLATTEN
#endif
/// A small operation on reals (a vector's sum, a dot product): inlined where fixed64's arithmetic
/// is, one flattened function elsewhere.
#define FIXED64_SMALL_OPERATION FIXED64_INLINE FIXED64_FLATTEN

namespace fixedpoint {

/// Number of results that saturated (overflow, division by zero, domain errors) since the
/// process started or since the last reset. Tests and benchmarks read it; one plain process-wide
/// counter (src/saturation.cpp), not synchronised between threads.
std::uint64_t saturation_count() noexcept;
void reset_saturation_count() noexcept;

namespace detail {
void count_saturation() noexcept;

constexpr std::int64_t kRawMax = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kRawMin = std::numeric_limits<std::int64_t>::min();

FIXED64_INLINE constexpr std::uint64_t magnitude(std::int64_t v) {
  return v < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
}

/// Gives sign * m as a raw value, saturating (and counting) when it is out of range.
constexpr std::int64_t signed_from_magnitude(bool negative, Uint128 m) {
  constexpr std::uint64_t kLimit = std::uint64_t{1} << 63;
  if (m.hi != 0 || m.lo > kLimit || (m.lo == kLimit && !negative)) {
    count_saturation();
    return negative ? kRawMin : kRawMax;
  }
  return negative ? static_cast<std::int64_t>(std::uint64_t{0} - m.lo) : static_cast<std::int64_t>(m.lo);
}

/// Gives sign * m as a raw value, saturating (and counting) when it is out of range.
constexpr std::int64_t signed_from_magnitude(bool negative, std::uint64_t m) {
  constexpr std::uint64_t kLimit = std::uint64_t{1} << 63;
  if (m > kLimit || (m == kLimit && !negative)) {
    count_saturation();
    return negative ? kRawMin : kRawMax;
  }
  return negative ? static_cast<std::int64_t>(std::uint64_t{0} - m) : static_cast<std::int64_t>(m);
}

/// round(n / d) (halves away from zero) as a raw value of the given sign, d != 0; saturates
/// (and counts) when it is out of range.
constexpr std::int64_t divide_rounded(bool negative, Uint128 n, std::uint64_t d) {
  if (n.hi >= d) {  // the quotient would not even fit 64 bits
    count_saturation();
    return negative ? kRawMin : kRawMax;
  }
  const Division qr = divide(n, d);
  // 2r >= d rounds up; a quotient of 2^64 - 1 stays as it is, which saturates all the same.
  const std::uint64_t rounded = qr.quotient + (qr.remainder >= d - qr.remainder ? 1u : 0u);
  return signed_from_magnitude(negative, rounded < qr.quotient ? qr.quotient : rounded);
}

/// round(n / d) (halves away from zero) as a raw value of the given sign, for n whose low bit
/// is 0 and 0 < d < 2^32 (fixed64's common division, d given normalised); saturates (and
/// counts) when out of range.
constexpr std::int64_t divide_rounded(bool negative, std::uint64_t n, const NormalisedDivisor& nd) {
  const Division qr = divide(n, nd);
  const std::uint32_t d = nd.divisor >> nd.shift;
  // 2r >= d rounds up; q + 1 cannot wrap, as q <= n / 2 for d >= 2 and r = 0 for d = 1.
  return signed_from_magnitude(negative, qr.quotient + (qr.remainder >= d - qr.remainder ? 1u : 0u));
}
constexpr std::int64_t divide_rounded(bool negative, std::uint64_t n, std::uint32_t d) {
  return divide_rounded(negative, n, normalise(d));
}

/// Rounds m / 2^s to nearest (halves away from zero), 0 <= s < 128.
constexpr Uint128 shift_right_rounded(Uint128 m, int s) {
  if (s == 0) return m;
  return shift_right(m + shift_left(Uint128{0, 1}, s - 1), s);
}
}  // namespace detail

/// A signed fixed-point number: raw() / 2^F, with raw() a 64-bit integer. Every operation that
/// cannot represent its exact result rounds to nearest; results past the range saturate to
/// max() or lowest() and increment saturation_count().
template <int F>
class fixed64 {
  static_assert(F >= 1 && F <= 32, "fixed64 keeps between 1 and 32 fraction bits, so every int fits");

 public:
  static constexpr int kFractionBits = F;

  constexpr fixed64() = default;
  /// Exact and implicit, so that `x * 2` and `x < 0` work: F <= 32 leaves 31 integer bits. A
  /// template taking `int` alone, so that `real x = 0.5;` does not compile (a plain int
  /// constructor would take 0.5 as 0); `real(0.5)` states the conversion.
  template <class I, std::enable_if_t<std::is_same<I, int>::value, int> = 0>
  FIXED64_INLINE constexpr fixed64(I value)  // NOLINT(google-explicit-constructor)
      : raw_(static_cast<std::int64_t>(static_cast<std::uint64_t>(static_cast<std::int64_t>(value)) << F)) {}
  /// Other integer types: explicit, saturating (and counting) when out of range.
  template <class I, std::enable_if_t<std::is_integral<I>::value && !std::is_same<I, int>::value &&
                                          !std::is_same<I, bool>::value,
                                      long> = 0>
  constexpr explicit fixed64(I value) : raw_(from_integer(value)) {}
  /// Rounds to nearest; meant for constexpr set-up (`static constexpr T kHalf = T(0.5)`), as it
  /// is floating-point arithmetic. Out-of-range values saturate; NaN gives 0; both count.
  template <class R, std::enable_if_t<std::is_floating_point<R>::value, int> = 0>
  constexpr explicit fixed64(R value) : raw_(from_double(static_cast<double>(value))) {}

  FIXED64_INLINE static constexpr fixed64 from_raw(std::int64_t raw) {
    fixed64 x;
    x.raw_ = raw;
    return x;
  }
  FIXED64_INLINE constexpr std::int64_t raw() const { return raw_; }

  /// Truncates toward zero, as a C cast from double does; saturates to the integer type's range.
  template <class I, std::enable_if_t<std::is_integral<I>::value && !std::is_same<I, bool>::value, int> = 0>
  FIXED64_INLINE constexpr explicit operator I() const {
    const std::int64_t whole = raw_ >= 0 ? raw_ >> F : -static_cast<std::int64_t>(detail::magnitude(raw_) >> F);
    if (std::is_signed<I>::value) {
      if (whole > static_cast<std::int64_t>(std::numeric_limits<I>::max())) return std::numeric_limits<I>::max();
      if (whole < static_cast<std::int64_t>(std::numeric_limits<I>::min())) return std::numeric_limits<I>::min();
      return static_cast<I>(whole);
    }
    if (whole < 0) return 0;
    if (static_cast<std::uint64_t>(whole) > static_cast<std::uint64_t>(std::numeric_limits<I>::max()))
      return std::numeric_limits<I>::max();
    return static_cast<I>(whole);
  }
  FIXED64_INLINE constexpr explicit operator bool() const { return raw_ != 0; }
  /// Rounds to nearest (one rounding for double and for float).
  constexpr explicit operator double() const { return static_cast<double>(raw_) / kScale; }
  constexpr explicit operator float() const {
    return static_cast<float>(raw_) / static_cast<float>(kScale);
  }
  constexpr explicit operator long double() const { return static_cast<long double>(raw_) / kScale; }

  FIXED64_INLINE friend constexpr fixed64 operator+(fixed64 x) { return x; }
  FIXED64_INLINE friend constexpr fixed64 operator-(fixed64 x) {
    if (x.raw_ == detail::kRawMin) {
      detail::count_saturation();
      return from_raw(detail::kRawMax);
    }
    return from_raw(-x.raw_);
  }

  FIXED64_INLINE friend constexpr fixed64 operator+(fixed64 a, fixed64 b) {
    const std::int64_t sum =
        static_cast<std::int64_t>(static_cast<std::uint64_t>(a.raw_) + static_cast<std::uint64_t>(b.raw_));
    // Overflow happened iff both operands have the same sign and the sum's sign differs.
    if ((a.raw_ < 0) == (b.raw_ < 0) && (sum < 0) != (a.raw_ < 0)) return saturated(a.raw_ < 0);
    return from_raw(sum);
  }
  FIXED64_INLINE friend constexpr fixed64 operator-(fixed64 a, fixed64 b) {
    const std::int64_t difference =
        static_cast<std::int64_t>(static_cast<std::uint64_t>(a.raw_) - static_cast<std::uint64_t>(b.raw_));
    if ((a.raw_ < 0) != (b.raw_ < 0) && (difference < 0) != (a.raw_ < 0)) return saturated(a.raw_ < 0);
    return from_raw(difference);
  }
  /// Rounded to nearest (halves away from zero): error at most half an ulp. Operands that fit
  /// int32 (|x| < 2^(31-F): 256 for S40.23) take one signed 32 x 32 -> 64-bit product, those
  /// whose magnitudes fit 32 bits one unsigned product; neither can saturate. Larger operands
  /// take the 128-bit product.
  FIXED64_INLINE friend constexpr fixed64 operator*(fixed64 a, fixed64 b) {
    // Written so that GCC emits one SMULL and tests the high words with two EORs (ARMv5TE).
    const auto a32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(a.raw_));
    const auto b32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(b.raw_));
    const std::int64_t product = std::int64_t{a32} * b32;
    if (__builtin_expect(((a.raw_ ^ a32) | (b.raw_ ^ b32)) == 0, 1)) {
      // floor((p + 2^(F-1) - 1) / 2^F) for p < 0 is -round(|p| / 2^F) with halves away from 0.
      return from_raw((product + (std::int64_t{1} << (F - 1)) - (product < 0 ? 1 : 0)) >> F);
    }
    const bool negative = (a.raw_ ^ b.raw_) < 0;
    const std::uint64_t ma = detail::magnitude(a.raw_), mb = detail::magnitude(b.raw_);
    if (__builtin_expect(((ma | mb) >> 32) == 0, 1)) {
      const std::uint64_t magnitudes = std::uint64_t{static_cast<std::uint32_t>(ma)} * static_cast<std::uint32_t>(mb);
      const std::uint64_t m = (magnitudes + (std::uint64_t{1} << (F - 1))) >> F;  // below 2^63
      return from_raw(negative ? -static_cast<std::int64_t>(m) : static_cast<std::int64_t>(m));
    }
    return multiply_general(negative, ma, mb);
  }
  /// Rounded to nearest (halves away from zero): error at most half an ulp. x / 0 saturates
  /// toward the sign of x (0 / 0 gives 0) and counts.
  FIXED64_FLATTEN friend constexpr fixed64 operator/(fixed64 a, fixed64 b) {
    const bool negative = (a.raw_ ^ b.raw_) < 0;
    const std::uint64_t m = detail::magnitude(a.raw_), d = detail::magnitude(b.raw_);
    // |a| 2^F within 64 bits and |b| within 32 (for S40.23: |a| < 2^18, 0 < |b| < 512): two
    // 32-bit quotient digits; otherwise the 128-by-64-bit division.
    if (__builtin_expect(((m >> (64 - F)) | (d >> 32)) == 0 && d != 0, 1))
      return from_raw(detail::divide_rounded(negative, m << F, static_cast<std::uint32_t>(d)));
    return divide_general(negative, a.raw_, m, d);
  }

  FIXED64_INLINE constexpr fixed64& operator+=(fixed64 b) { return *this = *this + b; }
  FIXED64_INLINE constexpr fixed64& operator-=(fixed64 b) { return *this = *this - b; }
  FIXED64_INLINE constexpr fixed64& operator*=(fixed64 b) { return *this = *this * b; }
  constexpr fixed64& operator/=(fixed64 b) { return *this = *this / b; }

  FIXED64_INLINE friend constexpr bool operator==(fixed64 a, fixed64 b) { return a.raw_ == b.raw_; }
  FIXED64_INLINE friend constexpr bool operator!=(fixed64 a, fixed64 b) { return a.raw_ != b.raw_; }
  FIXED64_INLINE friend constexpr bool operator<(fixed64 a, fixed64 b) { return a.raw_ < b.raw_; }
  FIXED64_INLINE friend constexpr bool operator<=(fixed64 a, fixed64 b) { return a.raw_ <= b.raw_; }
  FIXED64_INLINE friend constexpr bool operator>(fixed64 a, fixed64 b) { return a.raw_ > b.raw_; }
  FIXED64_INLINE friend constexpr bool operator>=(fixed64 a, fixed64 b) { return a.raw_ >= b.raw_; }

  /// Prints the value as a double would print (I/O only, never in the computing path).
  template <class CharT, class Traits>
  friend std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& out, fixed64 x) {
    return out << static_cast<double>(x);
  }

 private:
  static constexpr double kScale = static_cast<double>(std::int64_t{1} << F);

  /// The * and / of operands past their fast paths, kept out of line so that the inlined fast
  /// paths stay short.
  __attribute__((noinline)) FIXED64_FLATTEN static constexpr fixed64 multiply_general(bool negative, std::uint64_t ma,
                                                                                      std::uint64_t mb) {
    return from_raw(detail::signed_from_magnitude(negative, detail::shift_right_rounded(detail::multiply(ma, mb), F)));
  }
  __attribute__((noinline)) FIXED64_FLATTEN static constexpr fixed64 divide_general(bool negative, std::int64_t a,
                                                                                     std::uint64_t m, std::uint64_t d) {
    if (d == 0) {
      detail::count_saturation();
      return from_raw(a == 0 ? 0 : a < 0 ? detail::kRawMin : detail::kRawMax);
    }
    return from_raw(detail::divide_rounded(negative, detail::shift_left(detail::Uint128{0, m}, F), d));
  }

  static constexpr fixed64 saturated(bool negative) {
    detail::count_saturation();
    return from_raw(negative ? detail::kRawMin : detail::kRawMax);
  }

  template <class I>
  static constexpr std::int64_t from_integer(I value) {
    constexpr std::int64_t kLimit = detail::kRawMax >> F;  // largest whole number
    if (std::is_signed<I>::value) {
      const auto v = static_cast<std::int64_t>(value);
      if (v > kLimit || v < -kLimit - 1) {
        detail::count_saturation();
        return v < 0 ? detail::kRawMin : detail::kRawMax;
      }
      return static_cast<std::int64_t>(static_cast<std::uint64_t>(v) << F);
    }
    const auto v = static_cast<std::uint64_t>(value);
    if (v > static_cast<std::uint64_t>(kLimit)) {
      detail::count_saturation();
      return detail::kRawMax;
    }
    return static_cast<std::int64_t>(v << F);
  }

  static constexpr std::int64_t from_double(double value) {
    constexpr double kTwo63 = 9223372036854775808.0;
    const double scaled = value * kScale;  // exact: a power-of-two scaling
    if (!(scaled == scaled)) {
      detail::count_saturation();
      return 0;
    }
    if (scaled >= kTwo63 || scaled < -kTwo63) {
      detail::count_saturation();
      return scaled < 0 ? detail::kRawMin : detail::kRawMax;
    }
    std::int64_t whole = static_cast<std::int64_t>(scaled);  // toward zero, exact
    const double fraction = scaled - static_cast<double>(whole);  // exact
    if (fraction >= 0.5 && whole < detail::kRawMax) ++whole;
    if (fraction <= -0.5) --whole;
    return whole;
  }

  std::int64_t raw_ = 0;
};

/// x / d for several x over one d, each quotient bit for bit as operator/ gives it: a divisor
/// on operator/'s fast path (0 < |d| < 2^32 raw) is normalised and its reciprocal computed once,
/// which is most of a division's work; the others divide with operator/.
template <int F>
class fixed64_divisor {
 public:
  FIXED64_FLATTEN explicit constexpr fixed64_divisor(fixed64<F> d)
      : d_(d), fast_(d.raw() != 0 && (detail::magnitude(d.raw()) >> 32) == 0) {
    if (fast_) normalised_ = detail::normalise(static_cast<std::uint32_t>(detail::magnitude(d.raw())));
  }
  FIXED64_FLATTEN constexpr fixed64<F> divide(fixed64<F> a) const {
    const std::uint64_t m = detail::magnitude(a.raw());
    if (__builtin_expect(fast_ && (m >> (64 - F)) == 0, 1))
      return fixed64<F>::from_raw(detail::divide_rounded((a.raw() ^ d_.raw()) < 0, m << F, normalised_));
    return a / d_;
  }

 private:
  fixed64<F> d_;
  bool fast_;
  detail::NormalisedDivisor normalised_;
};

using s47_16 = fixed64<16>;
using s40_23 = fixed64<23>;

// ---------------------------------------------------------------------------------------------
// Exact functions: absolute value, square root and rounding to whole numbers.

/// |x|; |lowest()| saturates to max() and counts.
template <int F>
FIXED64_INLINE constexpr fixed64<F> abs(fixed64<F> x) {
  return x.raw() < 0 ? -x : x;
}
template <int F>
FIXED64_INLINE constexpr fixed64<F> fabs(fixed64<F> x) {
  return abs(x);
}

/// Square root, correctly rounded (error at most half an ulp): the integer square root of
/// raw * 2^F (below 2^64 by a corrected Newton estimate, above digit by digit on 128 bits),
/// rounded up when the remainder exceeds the root.
/// Domain x >= 0; a negative x gives 0 and counts as a saturation.
template <int F>
constexpr fixed64<F> sqrt(fixed64<F> x) {
  if (x.raw() < 0) {
    detail::count_saturation();
    return fixed64<F>();
  }
  const detail::SquareRoot s =
      detail::square_root(detail::shift_left(detail::Uint128{0, static_cast<std::uint64_t>(x.raw())}, F));
  // round(sqrt(n)) = root + 1 exactly when n - root^2 > root (n >= root^2 + root + 1).
  const bool up = s.remainder.hi != 0 || s.remainder.lo > s.root;
  return fixed64<F>::from_raw(static_cast<std::int64_t>(s.root + (up ? 1u : 0u)));
}

/// sqrt(x[0]^2 + ... + x[n-1]^2) from the exact sum of the raw squares: correctly rounded while
/// that sum stays below 2^64 (|x| below 2^(32-F) for one element: 512 for S40.23), above it
/// within 2^-31 relative (the sum's top 64 bits, an even shift, give the root); a norm past
/// max() saturates and counts. MINPACK's enorm for fixed point: integers have none of the
/// overflow and underflow of floating-point squares that its three scaled sums avoid, and one
/// unsigned 32 x 32-bit product and a 96-bit add per element replace a rounded multiply and a
/// saturating add.
template <int F>
constexpr fixed64<F> euclidean_norm(int n, const fixed64<F>* x) {
  constexpr std::uint64_t kCap = std::uint64_t{1} << 62;  // a sum at or past 2^126 saturates the norm
  std::uint64_t low = 0, high = 0;                        // the sum of squares, high * 2^64 + low
  // The int32 elements' squares (below 2^62) summed by their low and high 32-bit words apart:
  // two 32-bit additions with carry each on ARMv5TE, no carry test; folded in at the end.
  std::uint64_t low_words = 0, high_words = 0;
  for (int i = 0; i < n; ++i) {
    const std::int64_t v = x[i].raw();
    const auto v32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(v));
    if (__builtin_expect(v == v32, 1)) {
      const auto square = static_cast<std::uint64_t>(std::int64_t{v32} * v32);
      low_words += static_cast<std::uint32_t>(square);
      high_words += square >> 32;
      continue;
    }
    const std::uint64_t m = detail::magnitude(v);
    if ((m >> 32) == 0) {
      const std::uint64_t square = std::uint64_t{static_cast<std::uint32_t>(m)} * static_cast<std::uint32_t>(m);
      low += square;
      high += low < square ? 1u : 0u;
    } else {
      const detail::Uint128 square = detail::multiply(m, m);
      low += square.lo;
      high += square.hi + (low < square.lo ? 1u : 0u);
      if (high > kCap) high = kCap;  // the other branches add at most n more: no wrap-around
    }
  }
  const detail::Uint128 words = detail::Uint128{high_words >> 32, high_words << 32} + detail::Uint128{0, low_words};
  const detail::Uint128 sum = detail::Uint128{high, low} + words;
  high = sum.hi;
  low = sum.lo;
  if (high >= kCap) {
    detail::count_saturation();
    return std::numeric_limits<fixed64<F>>::max();
  }
  if (high == 0) {
    const detail::SquareRoot s = detail::square_root(low);
    return fixed64<F>::from_raw(static_cast<std::int64_t>(s.root + (s.remainder.lo > s.root ? 1u : 0u)));
  }
  const int k = (64 - detail::leading_zeros(high) + 1) / 2;  // sum / 4^k < 2^64
  const std::uint64_t top = detail::shift_right(detail::Uint128{high, low}, 2 * k).lo;
  const std::uint64_t root = detail::square_root(top).root;  // floor(sqrt(sum) / 2^k)
  return fixed64<F>::from_raw(static_cast<std::int64_t>((root << k) + (std::uint64_t{1} << (k - 1))));
}

/// a[0] b[0] + ... + a[n-1] b[n-1] with one rounding: the raw products are summed exactly (128
/// bits) and the sum is rounded to nearest (halves away from zero) once, so the error is at most
/// half an ulp; a sum past the range saturates and counts (as does one whose partial sum passed
/// 2^(126-F) times max(), where the exact sum would need more than 128 bits). Operands that fit int32 take one
/// signed 32 x 32-bit product each, and no rounding or saturation test per element.
template <int F>
constexpr fixed64<F> dot_product(int n, const fixed64<F>* a, const fixed64<F>* b) {
  constexpr std::int64_t kCap = std::int64_t{1} << 62;  // |sum| at or past 2^126 saturates the result
  std::uint64_t low = 0;
  std::int64_t high = 0;  // the sum, high * 2^64 + low (two's complement)
  int saturated = 0;      // the sign of a partial sum that passed the cap
  // The int32 products' low and high words, summed apart (two 32-bit additions with carry each
  // on ARMv5TE) and folded into the sum before each cap test and at the end.
  std::uint64_t low_words = 0;
  std::int64_t high_words = 0;
  const auto fold = [&] {
    const std::uint64_t shifted = static_cast<std::uint64_t>(high_words) << 32;
    const std::uint64_t part = shifted + low_words;
    const std::uint64_t sum = low + part;
    high += (high_words >> 32) + (part < shifted ? 1 : 0) + (sum < low ? 1 : 0);
    low = sum;
    low_words = 0;
    high_words = 0;
  };
  for (int i = 0; i < n && saturated == 0; ++i) {
    const std::int64_t x = a[i].raw(), y = b[i].raw();
    const auto x32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(x));
    const auto y32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(y));
    if (__builtin_expect(((x ^ x32) | (y ^ y32)) == 0, 1)) {
      const std::int64_t product = std::int64_t{x32} * y32;
      low_words += static_cast<std::uint32_t>(static_cast<std::uint64_t>(product));
      high_words += static_cast<std::int32_t>(static_cast<std::uint64_t>(product) >> 32);
    } else {
      fold();
      detail::Uint128 m = detail::multiply(detail::magnitude(x), detail::magnitude(y));
      if ((x ^ y) < 0) m = detail::Uint128{0, 0} - m;
      const std::uint64_t sum = low + m.lo;
      high += static_cast<std::int64_t>(m.hi) + (sum < low ? 1 : 0);
      low = sum;
      // Past 2^126 a partial sum is 2^(126-F) times max(): sticky, as a running sum would be.
      if (high > kCap || high < -kCap) saturated = high < 0 ? -1 : 1;
    }
  }
  if (saturated != 0) {
    detail::count_saturation();
    return saturated < 0 ? std::numeric_limits<fixed64<F>>::lowest() : std::numeric_limits<fixed64<F>>::max();
  }
  fold();
  const bool negative = high < 0;
  detail::Uint128 m{static_cast<std::uint64_t>(high), low};
  if (negative) m = detail::Uint128{0, 0} - m;
  return fixed64<F>::from_raw(detail::signed_from_magnitude(negative, detail::shift_right_rounded(m, F)));
}

namespace detail {
/// The few-pairs dot products' fast path: adds the raw x y to `sum` with one signed 32 x 32-bit
/// product, and marks `slow` when x or y does not fit int32 or the sum leaves 64 bits.
template <bool kSubtract = false>
__attribute__((always_inline)) constexpr void add_raw_product(std::int64_t x, std::int64_t y, std::int64_t& sum,
                                                              bool& slow) {
  const auto x32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(x));
  const auto y32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(y));
  slow |= ((x ^ x32) | (y ^ y32)) != 0;
  if (kSubtract)
    slow |= __builtin_sub_overflow(sum, std::int64_t{x32} * y32, &sum);
  else
    slow |= __builtin_add_overflow(sum, std::int64_t{x32} * y32, &sum);
}

/// round(sum / 2^F), halves away from zero, as a raw value; marks `slow` when that leaves 64 bits.
template <int F>
__attribute__((always_inline)) constexpr std::int64_t rounded_raw_sum(std::int64_t sum, bool& slow) {
  // floor((s + 2^(F-1) - 1) / 2^F) for s < 0 is -round(|s| / 2^F) with halves away from 0.
  std::int64_t rounded = 0;
  slow |= __builtin_add_overflow(sum, (std::int64_t{1} << (F - 1)) - (sum < 0 ? 1 : 0), &rounded);
  return rounded >> F;
}

/// dot_product over two or three pairs passed by value: the few-pairs forms' slow path, out of
/// line so that their fast path keeps the operands in registers.
template <int F>
__attribute__((noinline)) constexpr fixed64<F> dot_product_of_pairs(fixed64<F> a0, fixed64<F> b0, fixed64<F> a1,
                                                                    fixed64<F> b1, fixed64<F> a2, fixed64<F> b2) {
  const fixed64<F> a[3] = {a0, a1, a2}, b[3] = {b0, b1, b2};
  return dot_product(3, a, b);
}
}  // namespace detail

/// a0 b0 + a1 b1 (+ a2 b2) as dot_product gives it (the exact sum, rounded once), inline for
/// the per-point loops (a 3-vector's rotation, cross product or projection): when every operand
/// fits int32 (|x| < 256 for S40.23), one signed 32 x 32-bit product each and a 64-bit sum; any
/// other operand, or a sum past 64 bits, takes dot_product.
template <int F>
__attribute__((always_inline)) constexpr fixed64<F> dot_product(fixed64<F> a0, fixed64<F> b0, fixed64<F> a1,
                                                                fixed64<F> b1) {
  std::int64_t sum = 0;
  bool slow = false;
  detail::add_raw_product(a0.raw(), b0.raw(), sum, slow);
  detail::add_raw_product(a1.raw(), b1.raw(), sum, slow);
  const std::int64_t rounded = detail::rounded_raw_sum<F>(sum, slow);
  if (__builtin_expect(slow, 0)) return detail::dot_product_of_pairs(a0, b0, a1, b1, fixed64<F>(), fixed64<F>());
  return fixed64<F>::from_raw(rounded);
}
/// a0 b0 - a1 b1 as dot_product gives a0 b0 + (-a1) b1 (a1 = lowest() counts as -max()),
/// inline as the few-pairs dot_product: a cross product's components.
template <int F>
__attribute__((always_inline)) constexpr fixed64<F> difference_of_products(fixed64<F> a0, fixed64<F> b0,
                                                                           fixed64<F> a1, fixed64<F> b1) {
  std::int64_t sum = 0;
  bool slow = false;
  detail::add_raw_product(a0.raw(), b0.raw(), sum, slow);
  detail::add_raw_product<true>(a1.raw(), b1.raw(), sum, slow);
  const std::int64_t rounded = detail::rounded_raw_sum<F>(sum, slow);
  if (__builtin_expect(slow, 0)) return detail::dot_product_of_pairs(a0, b0, -a1, b1, fixed64<F>(), fixed64<F>());
  return fixed64<F>::from_raw(rounded);
}
template <int F>
__attribute__((always_inline)) constexpr fixed64<F> dot_product(fixed64<F> a0, fixed64<F> b0, fixed64<F> a1,
                                                                fixed64<F> b1, fixed64<F> a2, fixed64<F> b2) {
  std::int64_t sum = 0;
  bool slow = false;
  detail::add_raw_product(a0.raw(), b0.raw(), sum, slow);
  detail::add_raw_product(a1.raw(), b1.raw(), sum, slow);
  detail::add_raw_product(a2.raw(), b2.raw(), sum, slow);
  const std::int64_t rounded = detail::rounded_raw_sum<F>(sum, slow);
  if (__builtin_expect(slow, 0)) return detail::dot_product_of_pairs(a0, b0, a1, b1, a2, b2);
  return fixed64<F>::from_raw(rounded);
}

/// y[i] += s * x[i] for i < n, bit for bit as those operators give it (each product rounded, each
/// sum saturating), but a scale s past the int32 range times an x[i] within it takes two
/// 32 x 32-bit products instead of operator*'s out-of-line 128-bit one: MINPACK's Householder
/// updates scale a column by a sum over the whole column.
template <int F>
constexpr void add_multiple(int n, fixed64<F> s, const fixed64<F>* x, fixed64<F>* y) {
  const std::int64_t sr = s.raw();
  const auto s32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(sr));
  if (sr == s32) {
    // operator*'s int32 path, written out so that the product stays one SMULL with s32 held
    // in a register (inlined, GCC otherwise multiplies the sign-extended 64-bit values).
    for (int i = 0; i < n; ++i) {
      const std::int64_t xr = x[i].raw();
      const auto x32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(xr));
      if (__builtin_expect(xr != x32, 0)) {
        y[i] += s * x[i];
        continue;
      }
      const std::int64_t product = std::int64_t{x32} * s32;
      y[i] += fixed64<F>::from_raw((product + (std::int64_t{1} << (F - 1)) - (product < 0 ? 1 : 0)) >> F);
    }
    return;
  }
  const std::uint64_t ms = detail::magnitude(sr);
  const std::uint64_t ms0 = ms & 0xffffffffu, ms1 = ms >> 32;
  for (int i = 0; i < n; ++i) {
    const std::int64_t xr = x[i].raw();
    const auto x32 = static_cast<std::int32_t>(static_cast<std::uint32_t>(xr));
    if (xr != x32) {
      y[i] += s * x[i];
      continue;
    }
    // |s| |x| = ms1 |x| 2^32 + ms0 |x|, below 2^95: detail::multiply(ms, |x|) with two partial
    // products, rounded and saturated as multiply_general does.
    const std::uint64_t mx = detail::magnitude(xr);
    const std::uint64_t low = ms0 * mx, high = ms1 * mx;
    const detail::Uint128 product = detail::Uint128{high >> 32, high << 32} + detail::Uint128{0, low};
    const bool negative = (sr ^ xr) < 0;
    y[i] += fixed64<F>::from_raw(
        detail::signed_from_magnitude(negative, detail::shift_right_rounded(product, F)));
  }
}

/// Largest whole number not above x; exact.
template <int F>
constexpr fixed64<F> floor(fixed64<F> x) {
  constexpr std::int64_t kFractionMask = (std::int64_t{1} << F) - 1;
  return fixed64<F>::from_raw(x.raw() & ~kFractionMask);
}

/// Smallest whole number not below x; saturates (and counts) above the largest whole number.
template <int F>
constexpr fixed64<F> ceil(fixed64<F> x) {
  constexpr std::int64_t kFractionMask = (std::int64_t{1} << F) - 1;
  if ((x.raw() & kFractionMask) == 0) return x;
  return floor(x) + fixed64<F>(1);
}

/// Nearest whole number, halves away from zero (as std::round); above the largest whole number
/// it saturates to that number and counts.
template <int F>
constexpr fixed64<F> round(fixed64<F> x) {
  constexpr std::int64_t kFractionMask = (std::int64_t{1} << F) - 1;
  const fixed64<F> half = fixed64<F>::from_raw(std::int64_t{1} << (F - 1));
  const fixed64<F> shifted = x + half;  // can overflow only for positive x
  if (x.raw() < 0 && (shifted.raw() & kFractionMask) == 0) return shifted - fixed64<F>(1);  // a tie
  return floor(shifted);
}

}  // namespace fixedpoint

/// Machine constants for MINPACK-style code: epsilon() and min() are one ulp, max() and
/// lowest() the ends of the range, round_error() half an ulp.
namespace std {
template <int F>
class numeric_limits<fixedpoint::fixed64<F>> {
  using T = fixedpoint::fixed64<F>;

 public:
  static constexpr bool is_specialized = true;
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = true;
  static constexpr bool has_infinity = false;
  static constexpr bool has_quiet_NaN = false;
  static constexpr bool has_signaling_NaN = false;
  static constexpr std::float_denorm_style has_denorm = std::denorm_absent;
  static constexpr bool has_denorm_loss = false;
  static constexpr std::float_round_style round_style = std::round_to_nearest;
  static constexpr bool is_iec559 = false;
  static constexpr bool is_bounded = true;
  static constexpr bool is_modulo = false;
  static constexpr int digits = 63;
  static constexpr int digits10 = 18;  // floor(63 * log10(2))
  static constexpr int max_digits10 = 0;
  static constexpr int radix = 2;
  static constexpr int min_exponent = 0;
  static constexpr int min_exponent10 = 0;
  static constexpr int max_exponent = 0;
  static constexpr int max_exponent10 = 0;
  static constexpr bool traps = false;
  static constexpr bool tinyness_before = false;

  static constexpr T min() noexcept { return T::from_raw(1); }
  static constexpr T lowest() noexcept { return T::from_raw(std::numeric_limits<std::int64_t>::min()); }
  static constexpr T max() noexcept { return T::from_raw(std::numeric_limits<std::int64_t>::max()); }
  static constexpr T epsilon() noexcept { return T::from_raw(1); }
  static constexpr T round_error() noexcept { return T::from_raw(std::int64_t{1} << (F - 1)); }
  static constexpr T infinity() noexcept { return T(); }
  static constexpr T quiet_NaN() noexcept { return T(); }
  static constexpr T signaling_NaN() noexcept { return T(); }
  static constexpr T denorm_min() noexcept { return T::from_raw(1); }
};
}  // namespace std

// sin, cos, tan, atan, atan2, asin, acos, exp, log: integer algorithms in their own header.
#include "real/fixed64_math.h"
