// SPDX-License-Identifier: BSD-3-Clause
/// The 128-bit unsigned arithmetic behind fixed64's * / and sqrt (fpm's IntermediateType, which
/// we cannot have: 32-bit ARM GCC has no __int128). Built from 32-bit limbs only, so the host and
/// the ARMv5TE target run the same code; every operation is exact. Division uses no divide
/// instruction (the PXA270 has none) and no libgcc division: a Newton reciprocal of the top
/// divisor digit and 32-bit quotient digits, each corrected against the remainder.
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

/// Number of leading zero bits of a nonzero 32-bit value (one CLZ on ARMv5TE; GCC and Clang
/// also evaluate the builtin in constant expressions).
constexpr int leading_zeros(std::uint32_t v) { return __builtin_clz(v); }

/// Number of leading zero bits of a nonzero 64-bit value.
constexpr int leading_zeros(std::uint64_t v) { return __builtin_clzll(v); }

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

/// Seeds of the reciprocal below: entry k is floor(2^25 / (k + 257)) - 2^16, which is 2^32 / d
/// rounded down to 17 bits at the top end of the interval [(k + 256) 2^23, (k + 257) 2^23) that
/// holds d's top nine bits, so it never exceeds 2^32 / d there (relative error below 2^-8).
struct ReciprocalSeeds {
  std::uint16_t entry[256] = {};
};
constexpr ReciprocalSeeds make_reciprocal_seeds() {
  ReciprocalSeeds seeds;
  for (std::uint32_t k = 0; k < 256; ++k)
    seeds.entry[k] = static_cast<std::uint16_t>((std::uint32_t{1} << 25) / (k + 257) - (std::uint32_t{1} << 16));
  return seeds;
}
inline constexpr ReciprocalSeeds kReciprocalSeeds = make_reciprocal_seeds();

/// v with 2^32 + v <= 2^64 / d, at most 4 below floor(2^64 / d) - 2^32, for a normalised d
/// (top bit set): the table seed refined by two Newton steps x' = x + x (2^64 - d x) / 2^64,
/// each rounded down, so the estimate stays below 2^64 / d while its relative error goes from
/// 2^-8 to 2^-16 to 2^-32. Checked for all 2^31 normalised d against 2^64 / d (4 below it at
/// worst); tests/ports/real checks a seeded sample in every build.
constexpr std::uint32_t reciprocal(std::uint32_t d) {
  // x0 = seed 2^16 <= 2^64 / d, error e0 = 2^64 - d x0 < 2^56 (computed modulo 2^64).
  const std::uint32_t seed = kReciprocalSeeds.entry[(d >> 23) - 256] + (std::uint32_t{1} << 16);
  const std::uint64_t e0 = std::uint64_t{0} - (std::uint64_t{d} * seed << 16);
  // x1 = x0 + x0 e0 / 2^64 in [2^32, 2^33); v1 = x1 - 2^32 and e1 = (2^64 - d x1) / 2^32.
  const std::uint64_t x1 =
      (std::uint64_t{seed} << 16) + ((std::uint64_t{seed} * static_cast<std::uint32_t>(e0 >> 24)) >> 24);
  const auto v1 = static_cast<std::uint32_t>(x1);
  const auto e1 =
      static_cast<std::uint32_t>((std::uint64_t{0} - (std::uint64_t{d} * v1 + (std::uint64_t{d} << 32))) >> 32);
  // x2 = x1 + x1 e1 / 2^32 / 2^32, of which 2^32 + v1 contributes e1 + v1 e1 / 2^32.
  return v1 + e1 + static_cast<std::uint32_t>((std::uint64_t{v1} * e1) >> 32);
}

/// One 32-bit quotient digit: u / d and its remainder for a normalised d with u < d 2^32, given
/// v = reciprocal(d). The estimate u (2^32 + v) / 2^64, rounded down, never exceeds the
/// quotient and falls short by at most 6; the remainder corrects it.
struct Digit {
  std::uint32_t quotient = 0;
  std::uint32_t remainder = 0;
};
constexpr Digit divide_digit(std::uint64_t u, std::uint32_t d, std::uint32_t v) {
  const auto u1 = static_cast<std::uint32_t>(u >> 32);
  std::uint32_t q = u1 + static_cast<std::uint32_t>((std::uint64_t{u1} * v + static_cast<std::uint32_t>(u)) >> 32);
  std::uint64_t r = u - std::uint64_t{q} * d;
  while (r >= d) {
    ++q;
    r -= d;
  }
  return {q, static_cast<std::uint32_t>(r)};
}

/// A nonzero divisor below 2^32 made ready for divide: shifted left by `shift` so that its top
/// bit is set, with that value's reciprocal. Most of a division's work, done once for several
/// dividends.
struct NormalisedDivisor {
  std::uint32_t divisor = 0;     ///< d 2^shift
  std::uint32_t reciprocal = 0;  ///< reciprocal(divisor)
  int shift = 0;
};
constexpr NormalisedDivisor normalise(std::uint32_t d) {
  const int s = leading_zeros(d);
  return {d << s, reciprocal(d << s), s};
}

/// Divides n by the normalised divisor: two digits of divide_digit.
constexpr Division divide(std::uint64_t n, const NormalisedDivisor& nd) {
  const int s = nd.shift;
  const std::uint32_t d = nd.divisor, v = nd.reciprocal;
  // n 2^s in two parts: its digits above the lowest (below 2^s d) and the lowest; s < 32.
  const std::uint64_t upper = n >> (32 - s);
  const auto lowest = static_cast<std::uint32_t>(n) << s;
  Digit high{0, static_cast<std::uint32_t>(upper)};  // a quotient below 2^32 skips the first digit
  if (upper >= d) high = divide_digit(upper, d, v);
  const Digit low = divide_digit((std::uint64_t{high.remainder} << 32) | lowest, d, v);
  return {(std::uint64_t{high.quotient} << 32) | low.quotient, low.remainder >> s};
}

/// Divides n by a nonzero d below 2^32.
constexpr Division divide(std::uint64_t n, std::uint32_t d) { return divide(n, normalise(d)); }

/// Divides `n` by `d` (d != 0, n.hi < d so that the quotient fits in 64 bits).
/// Knuth's algorithm D with base 2^32: the divisor is normalised so that its top bit is set,
/// then each 32-bit quotient digit is estimated from the top two dividend digits and the top
/// divisor digit (through its reciprocal, as the core has no divide instruction), and corrected
/// against the second divisor digit, which makes it exact for a two-digit divisor.
constexpr Division divide(Uint128 n, std::uint64_t d) {
  if (n.hi == 0 && (d >> 32) == 0) return divide(n.lo, static_cast<std::uint32_t>(d));
  const int s = leading_zeros(d);
  d <<= s;
  const auto d1 = static_cast<std::uint32_t>(d >> 32), d0 = static_cast<std::uint32_t>(d);
  const std::uint32_t v = reciprocal(d1);
  const Uint128 ns = shift_left(n, s);  // n.hi < d before the shift, so nothing is lost
  const std::uint64_t top = ns.hi;      // dividend digits 3 and 2
  const auto n1 = static_cast<std::uint32_t>(ns.lo >> 32), n0 = static_cast<std::uint32_t>(ns.lo);

  // One quotient digit of (high * 2^32 + next) / d, where high < d.
  auto digit = [d1, d0, v](std::uint64_t high, std::uint32_t next) {
    std::uint32_t q = 0xffffffffu;
    std::uint64_t r = 0;
    if ((high >> 32) >= d1) {
      r = high - std::uint64_t{q} * d1;  // may reach 2^32, which ends the test below
    } else {
      const Digit estimate = divide_digit(high, d1, v);
      q = estimate.quotient;
      r = estimate.remainder;
    }
    while ((r >> 32) == 0 && std::uint64_t{q} * d0 > ((r << 32) | next)) {
      --q;
      r += d1;
    }
    return q;
  };
  const std::uint32_t q1 = digit(top, n1);
  const std::uint64_t mid = ((top << 32) | n1) - q1 * d;  // < d, exact modulo 2^64
  const std::uint32_t q0 = digit(mid, n0);
  const std::uint64_t rem = ((mid << 32) | n0) - q0 * d;
  return {(std::uint64_t{q1} << 32) | q0, rem >> s};
}

/// floor(sqrt(n)) and n - floor(sqrt(n))^2.
struct SquareRoot {
  std::uint64_t root = 0;
  Uint128 remainder;
};

/// floor(sqrt(n)) digit by digit (two bits of n per result bit): builds the seeds below.
constexpr std::uint64_t bitwise_square_root(std::uint64_t n) {
  std::uint64_t rest = n, root = 0;
  for (std::uint64_t bit = std::uint64_t{1} << 62; bit != 0; bit >>= 2) {
    const std::uint64_t trial = root + bit;
    root >>= 1;
    if (trial <= rest) {
      rest -= trial;
      root += bit;
    }
  }
  return root;
}

/// Seeds of the inverse square root: entry k - 64 is 2^30 / sqrt(T) at the middle of
/// T's interval [k / 256, (k + 1) / 256), k = 64..255 (T in [1/4, 1)), to about 9 bits.
struct InverseRootSeeds {
  std::uint32_t entry[192] = {};
};
constexpr InverseRootSeeds make_inverse_root_seeds() {
  InverseRootSeeds seeds;
  for (std::uint64_t k = 64; k < 256; ++k)  // sqrt(2^69 / (2k + 1)), to 3 bits fewer
    seeds.entry[k - 64] = static_cast<std::uint32_t>(bitwise_square_root((std::uint64_t{1} << 63) / (2 * k + 1)) << 3);
  return seeds;
}
inline constexpr InverseRootSeeds kInverseRootSeeds = make_inverse_root_seeds();

/// One Newton step y' = y + y (1 - t y^2) / 2 for y ~ 1 / sqrt(t), y in Q30, t in Q32.
constexpr std::uint32_t inverse_root_step(std::uint32_t y, std::uint32_t t) {
  const std::uint64_t y2 = (std::uint64_t{y} * y) >> 30;                   // Q30, at most 2^32
  const std::uint64_t ty2 = (std::uint64_t{t} * y2) >> 30;                 // Q32, close to 2^32
  const auto e = static_cast<std::int64_t>((std::uint64_t{1} << 32) - ty2);  // 1 - t y^2, Q32
  return static_cast<std::uint32_t>(static_cast<std::int64_t>(y) + ((static_cast<std::int64_t>(y) * e) >> 33));
}

/// floor(sqrt(n)) for n < 2^64 without a loop over the bits: n is shifted by an even count into
/// [2^62, 2^64), its top 32 bits t give 1 / sqrt(t) from a 9-bit seed and two Newton steps
/// (about 30 bits), t / sqrt(t) estimates the root, and the root is then corrected until
/// root^2 <= n < (root + 1)^2, which makes it exact whatever the estimate (on 10^7 seeded n the
/// estimate was off by at most 4, and by none in 91 %).
constexpr SquareRoot square_root(std::uint64_t n) {
  if (n == 0) return {};
  const int s = leading_zeros(n) & ~1;
  const auto t = static_cast<std::uint32_t>((n << s) >> 32);  // in [2^30, 2^32)
  std::uint32_t y = kInverseRootSeeds.entry[(t >> 24) - 64];
  y = inverse_root_step(y, t);
  y = inverse_root_step(y, t);
  const std::uint64_t estimate = ((std::uint64_t{t} * y) >> 30) >> (s / 2);
  auto root = static_cast<std::uint32_t>(estimate > 0xffffffffu ? 0xffffffffu : estimate);
  while (std::uint64_t{root} * root > n) --root;
  while (root != 0xffffffffu && std::uint64_t{root + 1} * (root + 1) <= n) ++root;
  return {root, Uint128{0, n - std::uint64_t{root} * root}};
}

constexpr SquareRoot square_root(Uint128 n) {
  if (n.hi == 0) return square_root(n.lo);  // the common case, in 64-bit registers
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
