// SPDX-License-Identifier: BSD-3-Clause
/// Test helpers for fixed64: a seeded operand generator that favours the range ends, an exact
/// reference in plain schoolbook arithmetic (independent of wide_uint.h), the ulp error
/// bookkeeping, and printing of a value with its raw integer in hex (as fpm's PrintTo does).
#pragma once

#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "real/fixed64.h"

namespace fixed64_test {

/// "1.5 (raw 0x0000000000c00000)".
template <int F>
std::string describe(fixedpoint::fixed64<F> x) {
  char text[96];
  std::snprintf(text, sizeof text, "%.17Lg (raw 0x%016" PRIx64 ")", static_cast<long double>(x),
                static_cast<std::uint64_t>(x.raw()));
  return text;
}

template <int F>
const char* type_name() {
  return F == 16 ? "s47_16" : F == 23 ? "s40_23" : "fixed64";
}

/// splitmix64: small, seeded, identical on every platform.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, n).
  std::uint64_t below(std::uint64_t n) { return next() % n; }
  /// A raw value with a random bit length in [0, max_bits], random sign and bits; one draw in
  /// eight is within 2^16 of a range end instead.
  std::int64_t raw(int max_bits = 63) {
    if (max_bits >= 63 && below(8) == 0) {
      const std::int64_t offset = static_cast<std::int64_t>(below(std::uint64_t{1} << 16));
      return below(2) ? INT64_MAX - offset : INT64_MIN + offset;
    }
    const int bits = static_cast<int>(below(static_cast<std::uint64_t>(max_bits) + 1));
    const std::uint64_t magnitude = bits == 0 ? 0 : next() >> (64 - bits);
    const auto value = static_cast<std::int64_t>(magnitude);  // below 2^63
    return below(2) ? -value : value;
  }
  /// A value uniform in [lo, hi] (as raw integers).
  std::int64_t uniform_raw(std::int64_t lo, std::int64_t hi) {
    const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    const std::uint64_t offset = span == UINT64_MAX ? next() : below(span + 1);
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + offset);
  }

 private:
  std::uint64_t state_;
};

/// A signed integer of up to 192 bits in 32-bit limbs, with schoolbook * and exact +, -, shifts:
/// the reference the 128-bit fixed64 operations are checked against.
class Exact {
 public:
  static constexpr int kLimbs = 6;
  Exact() = default;
  explicit Exact(std::int64_t v) : negative_(v < 0) {
    const std::uint64_t m = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    limb_[0] = static_cast<std::uint32_t>(m);
    limb_[1] = static_cast<std::uint32_t>(m >> 32);
  }
  static Exact power_of_two(int k) {
    Exact e;
    e.limb_[k / 32] = std::uint32_t{1} << (k % 32);
    return e;
  }
  friend Exact operator*(const Exact& a, const Exact& b) {
    Exact p;
    for (int i = 0; i < kLimbs; ++i) {
      std::uint64_t carry = 0;
      for (int j = 0; i + j < kLimbs; ++j) {
        const std::uint64_t t = std::uint64_t{a.limb_[i]} * b.limb_[j] + p.limb_[i + j] + carry;
        p.limb_[i + j] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
      }
    }
    p.negative_ = (a.negative_ != b.negative_) && !p.is_zero();
    return p;
  }
  friend Exact operator-(const Exact& a, const Exact& b) { return a + b.negated(); }
  friend Exact operator+(const Exact& a, const Exact& b) {
    if (a.negative_ == b.negative_) {
      Exact s = add_magnitudes(a, b);
      s.negative_ = a.negative_ && !s.is_zero();
      return s;
    }
    if (compare_magnitudes(a, b) >= 0) {
      Exact d = subtract_magnitudes(a, b);
      d.negative_ = a.negative_ && !d.is_zero();
      return d;
    }
    Exact d = subtract_magnitudes(b, a);
    d.negative_ = b.negative_ && !d.is_zero();
    return d;
  }
  Exact negated() const {
    Exact n = *this;
    n.negative_ = !negative_ && !is_zero();
    return n;
  }
  bool is_negative() const { return negative_; }
  bool is_zero() const {
    for (std::uint32_t l : limb_)
      if (l != 0) return false;
    return true;
  }
  /// a compared with b: -1, 0 or 1.
  static int compare(const Exact& a, const Exact& b) {
    const Exact d = a - b;
    return d.is_zero() ? 0 : d.is_negative() ? -1 : 1;
  }
  /// |a| compared with |b|: -1, 0 or 1.
  static int compare_magnitudes(const Exact& a, const Exact& b) {
    for (int i = kLimbs - 1; i >= 0; --i)
      if (a.limb_[i] != b.limb_[i]) return a.limb_[i] < b.limb_[i] ? -1 : 1;
    return 0;
  }
  long double to_long_double() const {
    long double v = 0;
    for (int i = kLimbs - 1; i >= 0; --i) v = v * 4294967296.0L + limb_[i];
    return negative_ ? -v : v;
  }

 private:
  static Exact add_magnitudes(const Exact& a, const Exact& b) {
    Exact s;
    std::uint64_t carry = 0;
    for (int i = 0; i < kLimbs; ++i) {
      const std::uint64_t t = std::uint64_t{a.limb_[i]} + b.limb_[i] + carry;
      s.limb_[i] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    return s;
  }
  static Exact subtract_magnitudes(const Exact& a, const Exact& b) {  // |a| >= |b|
    Exact d;
    std::int64_t borrow = 0;
    for (int i = 0; i < kLimbs; ++i) {
      std::int64_t t = std::int64_t{a.limb_[i]} - b.limb_[i] - borrow;
      borrow = t < 0;
      if (t < 0) t += std::int64_t{1} << 32;
      d.limb_[i] = static_cast<std::uint32_t>(t);
    }
    return d;
  }
  std::uint32_t limb_[kLimbs] = {};
  bool negative_ = false;
};

/// Worst error seen by one sweep, with the operands that produced it.
template <int F>
struct WorstError {
  long double ulps = -1;
  std::string where;
  /// Whether `error_ulps` is a new worst (then the caller describes the operands with record).
  bool beaten_by(long double error_ulps) const { return error_ulps > ulps; }
  void record(long double error_ulps, const std::string& operands) {
    ulps = error_ulps;
    where = operands;
  }
  void print(const char* op) const {
    std::printf("measured worst error of %s for %s: %.4Lf ulp at %s\n", op, type_name<F>(), ulps < 0 ? 0 : ulps,
                where.c_str());
  }
};

/// Prints the first few failures of a sweep in full; returns whether to keep printing.
inline bool report_failure(int& printed, const std::string& message) {
  if (printed >= 5) return false;
  ++printed;
  std::printf("  FAIL %s\n", message.c_str());
  return true;
}

}  // namespace fixed64_test
