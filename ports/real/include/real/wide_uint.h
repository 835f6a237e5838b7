// SPDX-License-Identifier: BSD-3-Clause
/// The 128-bit unsigned arithmetic behind fixed64's * / and sqrt (fpm's IntermediateType, which
/// we cannot have: 32-bit ARM GCC has no __int128). Built from 32-bit limbs only, so the host and
/// the ARMv5TE target run the same code; every operation is exact.
#pragma once

#include <cstdint>

namespace fixedpoint {
namespace detail {

/// An unsigned 128-bit integer `hi * 2^64 + lo`.
struct Uint128 {
  std::uint64_t hi = 0;
  std::uint64_t lo = 0;
};

constexpr bool operator==(Uint128 a, Uint128 b) { return a.hi == b.hi && a.lo == b.lo; }
constexpr bool operator<(Uint128 a, Uint128 b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
constexpr bool operator<=(Uint128 a, Uint128 b) { return !(b < a); }

constexpr Uint128 operator+(Uint128 a, Uint128 b) {
  const std::uint64_t lo = a.lo + b.lo;
  return {a.hi + b.hi + (lo < a.lo ? 1u : 0u), lo};
}

constexpr Uint128 operator-(Uint128 a, Uint128 b) {
  return {a.hi - b.hi - (a.lo < b.lo ? 1u : 0u), a.lo - b.lo};
}

/// Shifts left by 0 <= s < 128; bits shifted past 2^128 are lost.
constexpr Uint128 shift_left(Uint128 a, int s) {
  if (s == 0) return a;
  if (s >= 64) return {a.lo << (s - 64), 0};
  return {(a.hi << s) | (a.lo >> (64 - s)), a.lo << s};
}

/// Shifts right by 0 <= s < 128, truncating.
constexpr Uint128 shift_right(Uint128 a, int s) {
  if (s == 0) return a;
  if (s >= 64) return {0, a.hi >> (s - 64)};
  return {a.hi >> s, (a.lo >> s) | (a.hi << (64 - s))};
}

/// Number of leading zero bits of a nonzero 64-bit value.
constexpr int leading_zeros(std::uint64_t v) {
  int n = 0;
  if ((v >> 32) == 0) { n += 32; v <<= 32; }
  if ((v >> 48) == 0) { n += 16; v <<= 16; }
  if ((v >> 56) == 0) { n += 8; v <<= 8; }
  if ((v >> 60) == 0) { n += 4; v <<= 4; }
  if ((v >> 62) == 0) { n += 2; v <<= 2; }
  if ((v >> 63) == 0) { n += 1; }
  return n;
}

/// Exact 64 x 64 -> 128-bit product from four 32 x 32 -> 64-bit partial products (one UMULL
/// each on ARMv5TE).
constexpr Uint128 multiply(std::uint64_t a, std::uint64_t b) {
  constexpr std::uint64_t kLow = 0xffffffffu;
  const std::uint64_t a0 = a & kLow, a1 = a >> 32;
  const std::uint64_t b0 = b & kLow, b1 = b >> 32;
  const std::uint64_t p00 = a0 * b0;
  const std::uint64_t p01 = a0 * b1;
  const std::uint64_t p10 = a1 * b0;
  const std::uint64_t p11 = a1 * b1;
  // Sum of the middle column: three values below 2^32 each, so no overflow.
  const std::uint64_t middle = (p00 >> 32) + (p01 & kLow) + (p10 & kLow);
  return {p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32), (middle << 32) | (p00 & kLow)};
}

/// Quotient and remainder of a 128-by-64-bit division whose quotient fits in 64 bits.
struct Division {
  std::uint64_t quotient = 0;
  std::uint64_t remainder = 0;
};

/// Divides `n` by `d` (d != 0, n.hi < d so that the quotient fits in 64 bits).
/// Knuth's algorithm D with base 2^32: the divisor is normalised so that its top bit is set,
/// then each 32-bit quotient digit is estimated from the top two dividend digits and the top
/// divisor digit, and corrected (at most twice) against the second divisor digit.
constexpr Division divide(Uint128 n, std::uint64_t d) {
  constexpr std::uint64_t kBase = std::uint64_t{1} << 32;
  constexpr std::uint64_t kLow = kBase - 1;
  const int s = leading_zeros(d);
  d <<= s;
  const std::uint64_t d1 = d >> 32, d0 = d & kLow;
  const Uint128 ns = shift_left(n, s);  // n.hi < d before the shift, so nothing is lost
  const std::uint64_t top = ns.hi;      // dividend digits 3 and 2
  const std::uint64_t n1 = ns.lo >> 32, n0 = ns.lo & kLow;

  // Estimates one quotient digit of (high * 2^32 + next) / d, where high < d.
  auto digit = [d1, d0, kBase](std::uint64_t high, std::uint64_t next) {
    std::uint64_t q = high / d1;
    std::uint64_t r = high - q * d1;
    while (q >= kBase || q * d0 > ((r << 32) | next)) {
      --q;
      r += d1;
      if (r >= kBase) break;
    }
    return q;
  };
  const std::uint64_t q1 = digit(top, n1);
  const std::uint64_t mid = ((top << 32) | n1) - q1 * d;  // < d, exact modulo 2^64
  const std::uint64_t q0 = digit(mid, n0);
  const std::uint64_t rem = ((mid << 32) | n0) - q0 * d;
  return {(q1 << 32) | q0, rem >> s};
}

/// floor(sqrt(n)) and n - floor(sqrt(n))^2, digit by digit (two bits of n per result bit).
struct SquareRoot {
  std::uint64_t root = 0;
  Uint128 remainder;
};

constexpr SquareRoot square_root(Uint128 n) {
  if (n.hi == 0) {  // the common case, in 64-bit registers (half the work on ARMv5TE)
    std::uint64_t rest = n.lo, root = 0;
    for (std::uint64_t bit = n.lo == 0 ? 0 : std::uint64_t{1} << ((63 - leading_zeros(n.lo)) & ~1); bit != 0;
         bit >>= 2) {
      const std::uint64_t trial = root + bit;
      root >>= 1;
      if (trial <= rest) {
        rest -= trial;
        root += bit;
      }
    }
    return {root, Uint128{0, rest}};
  }
  // Start at the highest power of four not above n.
  int bit_index = 0;
  if (n.hi != 0)
    bit_index = 64 + 63 - leading_zeros(n.hi);
  else if (n.lo != 0)
    bit_index = 63 - leading_zeros(n.lo);
  bit_index &= ~1;
  Uint128 bit = shift_left(Uint128{0, 1}, bit_index);
  Uint128 root;  // holds root * 2^(bit_index) scaled as in the classic shift-and-subtract method
  Uint128 rest = n;
  for (; bit_index >= 0; bit_index -= 2) {
    const Uint128 trial = root + bit;
    root = shift_right(root, 1);
    if (trial <= rest) {
      rest = rest - trial;
      root = root + bit;
    }
    bit = shift_right(bit, 2);
  }
  return {root.lo, rest};
}

}  // namespace detail
}  // namespace fixedpoint
