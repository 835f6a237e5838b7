// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_finite.h, the vnl_finite_int<N> part: the integers modulo N
/// (a field when N is prime) with their ring operations, inverses of units, orders, Euler's
/// totient and, for cyclic groups, a generator with discrete exp and log. Upstream's
/// vnl_finite_int_poly (polynomials over Z_N) is not ported.
#pragma once

#include <cassert>
#include <ostream>
#include <vector>

template <int N>
class vnl_finite_int {
  using Base = vnl_finite_int<N>;

 public:
  /// The number of elements, N.
  static unsigned int cardinality() { return N; }

  vnl_finite_int(int x = 0) : val_(((x % N) + N) % N) { static_assert(N > 1, "vnl_finite_int needs N > 1"); }
  operator int() const { return val_; }
  explicit operator long() const { return val_; }
  explicit operator short() const { return static_cast<short>(val_); }

  bool operator==(const Base& x) const { return val_ == x.val_; }
  bool operator!=(const Base& x) const { return val_ != x.val_; }
  bool operator==(int x) const { return *this == Base(x); }
  bool operator!=(int x) const { return !(*this == x); }
  Base operator-() const { return Base(N - val_); }
  Base operator+() const { return *this; }
  bool operator!() const { return val_ == 0; }

  Base& operator+=(const Base& r) { return *this = Base(val_ + r.val_); }
  Base& operator-=(const Base& r) { return *this = Base(val_ - r.val_); }
  Base& operator*=(const Base& r) {
    return *this = Base(static_cast<int>(static_cast<long long>(val_) * r.val_ % N));
  }
  /// Division by a unit (asserts that r is one).
  Base& operator/=(const Base& r) {
    assert(r.is_unit());
    return *this *= r.reciproc();
  }
  Base& operator++() { return *this += 1; }
  Base& operator--() { return *this -= 1; }

  /// gcd(val, N) == 1.
  bool is_unit() const { return gcd(val_, N) == 1; }
  /// A nonzero element that is not a unit.
  bool is_zero_divisor() const { return val_ != 0 && !is_unit(); }
  /// The multiplicative inverse of a unit.
  Base reciproc() const {
    assert(is_unit());
    int t = 0, new_t = 1, r = N, new_r = val_;  // extended Euclid
    while (new_r != 0) {
      const int q = r / new_r;
      const int tt = t - q * new_t;
      t = new_t, new_t = tt;
      const int rr = r - q * new_r;
      r = new_r, new_r = rr;
    }
    return Base(t);
  }
  /// x^r (r < 0 for units only).
  Base pow(int r) const {
    Base base = r < 0 ? reciproc() : *this, result(1);
    for (unsigned e = static_cast<unsigned>(r < 0 ? -r : r); e; e >>= 1, base *= base) {
      if (e & 1) result *= base;
    }
    return result;
  }
  /// The smallest k > 0 with k x = 0.
  unsigned int additive_order() const { return val_ == 0 ? 1 : static_cast<unsigned>(N / gcd(val_, N)); }
  /// The smallest k > 0 with x^k = 1 (units only; -1 otherwise, as upstream).
  int multiplicative_order() const {
    if (!is_unit()) return -1;
    Base x = *this;
    int k = 1;
    while (x != 1) x *= *this, ++k;
    return k;
  }
  /// The number of units, phi(N).
  static unsigned int totient() {
    unsigned count = 0;
    for (int x = 1; x < N; ++x) count += gcd(x, N) == 1;
    return count;
  }
  /// True when N is prime.
  static bool is_field() { return totient() == static_cast<unsigned>(N - 1); }
  /// The smallest unit whose powers give every unit (1 if the unit group is not cyclic).
  static Base smallest_generator() {
    for (int g = 1; g < N; ++g) {
      if (Base(g).multiplicative_order() == static_cast<int>(totient())) return Base(g);
    }
    return Base(1);
  }
  /// g^r for the smallest generator g; log() is its inverse on the units.
  static Base exp(int r) { return smallest_generator().pow(r); }
  unsigned int log() const {
    assert(is_unit());
    const Base g = smallest_generator();
    Base x(1);
    for (unsigned k = 0; k < totient(); ++k, x *= g) {
      if (x == *this) return k;
    }
    return 0;
  }
  /// The prime factors of N with multiplicity, ascending.
  static std::vector<unsigned int> decompose() {
    std::vector<unsigned int> factors;
    int n = N;
    for (int p = 2; p * p <= n; ++p) {
      while (n % p == 0) factors.push_back(static_cast<unsigned>(p)), n /= p;
    }
    if (n > 1) factors.push_back(static_cast<unsigned>(n));
    return factors;
  }

 private:
  static int gcd(int a, int b) {
    while (b != 0) {
      const int t = a % b;
      a = b, b = t;
    }
    return a < 0 ? -a : a;
  }
  int val_;
};

template <int N>
vnl_finite_int<N> operator+(vnl_finite_int<N> a, const vnl_finite_int<N>& b) {
  return a += b;
}
template <int N>
vnl_finite_int<N> operator-(vnl_finite_int<N> a, const vnl_finite_int<N>& b) {
  return a -= b;
}
template <int N>
vnl_finite_int<N> operator*(vnl_finite_int<N> a, const vnl_finite_int<N>& b) {
  return a *= b;
}
template <int N>
vnl_finite_int<N> operator/(vnl_finite_int<N> a, const vnl_finite_int<N>& b) {
  return a /= b;
}
template <int N>
std::ostream& operator<<(std::ostream& s, const vnl_finite_int<N>& r) {
  return s << int(r);
}
