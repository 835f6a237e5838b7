// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_finite.h: vnl_finite_int<N>, the integers modulo N (a field
/// when N is prime) with their ring operations, inverses of units, orders, Euler's totient
/// and, for cyclic groups, a generator with discrete exp and log; and vnl_finite_int_poly<N, M>,
/// the polynomials of degree below M over them, multiplied modulo a degree-M polynomial
/// (GF(N^M) when that one is irreducible and N prime).
#pragma once

#ifdef vnl_finite_h_
#error "edgetrack's drop-in vnl/vnl_finite.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <cstddef>
#include <ostream>
#include <utility>
#include <vector>

inline namespace edgetrack_ports {

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
  Base& operator*=(const Base& r) { return *this = Base(static_cast<int>(static_cast<long long>(val_) * r.val_ % N)); }
  /// Division by a unit (asserts that r is one).
  Base& operator/=(const Base& r) {
    assert(r.is_unit());
    return *this *= r.reciproc();
  }
  Base& operator++() { return *this += 1; }
  Base& operator--() { return *this -= 1; }

  /// gcd(val, N) == 1.
  bool is_unit() const { return gcd(static_cast<unsigned>(val_)) == 1; }
  /// Not a unit (0 included, as upstream: division by it is undefined).
  bool is_zero_divisor() const { return !is_unit(); }
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
  unsigned int additive_order() const { return val_ == 0 ? 1 : N / gcd(static_cast<unsigned>(val_)); }
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
    // Computed once per N (a constant of the type; C++ makes the first call's initialisation
    // thread-safe), as upstream caches it.
    static const unsigned int phi = [] {
      unsigned count = 0;
      for (unsigned x = 1; x < unsigned(N); ++x) count += gcd(x) == 1;
      return count;
    }();
    return phi;
  }
  /// True when N is prime.
  static bool is_field() { return totient() == static_cast<unsigned>(N - 1); }
  /// The smallest unit whose powers give every unit (1 if the unit group is not cyclic).
  static Base smallest_generator() {
    static const Base generator = [] {  // once per N, as totient()
      for (int g = 1; g < N; ++g) {
        if (Base(g).multiplicative_order() == static_cast<int>(totient())) return Base(g);
      }
      return Base(1);
    }();
    return generator;
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
  /// Greatest common divisor (gcd(0, n) is n).
  static unsigned int gcd(unsigned int l, unsigned int n) {
    while (l != 0) {
      const unsigned int t = n % l;
      n = l, l = t;
    }
    return n;
  }
  static unsigned int gcd(unsigned int l) { return gcd(l, N); }

 private:
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
// With an int on either side, as upstream (the int is taken modulo N).
template <int N>
vnl_finite_int<N> operator+(vnl_finite_int<N> a, int b) {
  return a += vnl_finite_int<N>(b);
}
template <int N>
vnl_finite_int<N> operator+(int a, vnl_finite_int<N> b) {
  return b += vnl_finite_int<N>(a);
}
template <int N>
vnl_finite_int<N> operator-(vnl_finite_int<N> a, int b) {
  return a -= vnl_finite_int<N>(b);
}
template <int N>
vnl_finite_int<N> operator-(int a, const vnl_finite_int<N>& b) {
  return vnl_finite_int<N>(a) - b;
}
template <int N>
vnl_finite_int<N> operator*(vnl_finite_int<N> a, int b) {
  return a *= vnl_finite_int<N>(b);
}
template <int N>
vnl_finite_int<N> operator*(int a, vnl_finite_int<N> b) {
  return b *= vnl_finite_int<N>(a);
}
template <int N>
vnl_finite_int<N> operator/(vnl_finite_int<N> a, int b) {
  return a /= vnl_finite_int<N>(b);
}
template <int N>
vnl_finite_int<N> operator/(int a, const vnl_finite_int<N>& b) {
  return vnl_finite_int<N>(a) / b;
}
template <int N>
std::ostream& operator<<(std::ostream& s, const vnl_finite_int<N>& r) {
  return s << int(r);
}

/// Polynomials of degree below M over Z_N: a0 + a1 X + ... + a_{M-1} X^{M-1}, added
/// coefficient-wise and multiplied modulo the degree-M polynomial set by modulo_polynomial().
/// As upstream, that polynomial is one process-wide setting per (N, M) (set it before the
/// first product; setting it again changes it for every such polynomial; not thread-safe).
template <int N, int M>
class vnl_finite_int_poly {
  using Base = vnl_finite_int_poly<N, M>;
  using Scalar = vnl_finite_int<N>;

 public:
  /// The number of such polynomials, N^M.
  static unsigned int cardinality() {
    unsigned int count = 1;
    for (int m = 0; m < M; ++m) count *= N;
    return count;
  }

  /// The coefficients a0, a1, ... (at most M of them).
  vnl_finite_int_poly(std::vector<Scalar> p)  // NOLINT(google-explicit-constructor): upstream's
      : val_(std::move(p)) {
    static_assert(N > 1 && M > 0, "vnl_finite_int_poly needs N > 1 and M > 0");
    assert(val_.size() <= static_cast<std::size_t>(M));
    if (val_.empty()) val_.push_back(Scalar(0));
  }
  /// The constant polynomial n.
  vnl_finite_int_poly(const Scalar& n) : val_(1, n) {}  // NOLINT(google-explicit-constructor)
  vnl_finite_int_poly() : val_(1, Scalar(0)) {}

  /// Formal degree (the number of stored coefficients minus 1).
  std::size_t deg() const { return val_.size() - 1; }
  /// Effective degree; -1 for the zero polynomial.
  int degree() const {
    for (int i = static_cast<int>(deg()); i >= 0; --i) {
      if (val_[i] != 0) return i;
    }
    return -1;
  }
  /// Coefficient i (0 beyond the stored ones).
  Scalar operator[](unsigned int i) const {
    assert(i < static_cast<unsigned>(M));
    return i <= deg() ? val_[i] : Scalar(0);
  }
  Base& operator=(const Scalar& n) {
    val_.assign(1, n);
    return *this;
  }

  bool operator==(const Base& x) const {
    const std::size_t top = deg() > x.deg() ? deg() : x.deg();
    for (unsigned i = 0; i <= top; ++i) {
      if ((*this)[i] != x[i]) return false;
    }
    return true;
  }
  bool operator!=(const Base& x) const { return !(*this == x); }
  bool operator==(const Scalar& x) const { return *this == Base(x); }
  bool operator!=(const Scalar& x) const { return !(*this == x); }

  Base operator-() const {
    std::vector<Scalar> p = val_;
    for (Scalar& c : p) c = -c;
    return p;
  }
  Base operator+() const { return *this; }
  /// True for the zero polynomial.
  bool operator!() const { return degree() < 0; }

  Base& operator+=(const Base& r) {
    if (r.deg() > deg()) val_.resize(r.deg() + 1, Scalar(0));
    for (unsigned i = 0; i <= r.deg(); ++i) val_[i] += r.val_[i];
    return *this;
  }
  Base& operator-=(const Base& r) { return *this += -r; }
  Base& operator*=(const Scalar& n) {
    for (Scalar& c : val_) c *= n;
    return *this;
  }
  /// The smallest r > 0 with r * x == 0.
  unsigned int additive_order() const {
    unsigned int r = N;
    for (const Scalar& c : val_) {
      if (c != 0) r = Scalar::gcd(static_cast<unsigned>(int(c)), r);
    }
    return N / r;
  }

  /// Sets (p: M + 1 coefficients, p[M] a unit) or gets (no argument) the modulus of the
  /// products. It is stored scaled so that its X^M coefficient is -1: then X^M is the sum of
  /// the lower terms, which is how products reduce.
  static std::vector<Scalar>& modulo_polynomial(std::vector<Scalar> p = std::vector<Scalar>()) {
    static std::vector<Scalar> modulus(M + 1, Scalar(0));  // process-wide per (N, M), as upstream
    if (p.empty()) {
      assert(modulus[M] != 0 && "vnl_finite_int_poly: modulo_polynomial not set");
    } else {
      assert(p.size() == static_cast<std::size_t>(M + 1) && p[M].is_unit());
      const Scalar scale = -(Scalar(1) / p[M]);
      for (int m = 0; m <= M; ++m) modulus[m] = scale * p[m];
    }
    return modulus;
  }

  /// The product modulo modulo_polynomial().
  Base& operator*=(const Base& r) {
    const std::vector<Scalar>& modulus = modulo_polynomial();
    std::vector<Scalar> product(2 * M - 1, Scalar(0));
    for (unsigned i = 0; i <= deg(); ++i) {
      for (unsigned j = 0; j <= r.deg(); ++j) product[i + j] += val_[i] * r.val_[j];
    }
    // X^k = X^(k-M) * X^M = X^(k-M) * (modulus[0] + ... + modulus[M-1] X^(M-1)), top down.
    for (int k = 2 * M - 2; k >= M; --k) {
      for (int m = 0; m < M; ++m) product[k - M + m] += product[k] * modulus[m];
    }
    product.resize(M);
    val_ = product;
    return *this;
  }
  /// The smallest r > 0 with x^r == 1; unsigned(-1) when there is none (x not a unit).
  unsigned int multiplicative_order() const {
    Base t = Scalar(1);
    unsigned int order = 0;
    do {
      t *= *this, ++order;
    } while (t != Scalar(1) && t != Scalar(0) && order < cardinality());
    return t == Scalar(1) ? order : static_cast<unsigned>(-1);
  }
  /// True when N is prime and the residue of X^M generates every nonzero element (upstream's
  /// test that the modulus makes a field).
  static bool is_field() {
    if (!Scalar::is_field()) return false;
    std::vector<Scalar> x_to_the_m = modulo_polynomial();
    x_to_the_m.pop_back();
    return Base(x_to_the_m).multiplicative_order() + 1 == cardinality();
  }
  /// A generator of the nonzero elements of a field (X^M reduced, as upstream); 1 otherwise.
  static Base smallest_generator() {
    if (!is_field()) return Scalar(1);
    std::vector<Scalar> x_to_the_m = modulo_polynomial();
    x_to_the_m.pop_back();
    return Base(x_to_the_m);
  }

 private:
  std::vector<Scalar> val_;  // coefficients a0, a1, ...; never empty
};

template <int N, int M>
vnl_finite_int_poly<N, M> operator+(vnl_finite_int_poly<N, M> r1, const vnl_finite_int_poly<N, M>& r2) {
  return r1 += r2;
}
template <int N, int M>
vnl_finite_int_poly<N, M> operator-(vnl_finite_int_poly<N, M> r1, const vnl_finite_int_poly<N, M>& r2) {
  return r1 -= r2;
}
template <int N, int M>
vnl_finite_int_poly<N, M> operator*(vnl_finite_int_poly<N, M> r1, const vnl_finite_int<N>& r2) {
  return r1 *= r2;
}
template <int N, int M>
vnl_finite_int_poly<N, M> operator*(const vnl_finite_int<N>& r2, vnl_finite_int_poly<N, M> r1) {
  return r1 *= r2;
}
template <int N, int M>
vnl_finite_int_poly<N, M> operator*(vnl_finite_int_poly<N, M> r1, const vnl_finite_int_poly<N, M>& r2) {
  return r1 *= r2;
}
/// Upstream's form: "1+2X+X^3", "0" for zero.
template <int N, int M>
std::ostream& operator<<(std::ostream& s, const vnl_finite_int_poly<N, M>& r) {
  bool any = false;
  for (unsigned i = 0; i <= r.deg(); ++i) {
    if (r[i] == 0) continue;
    if (any) s << '+';
    any = true;
    if (r[i] != 1 || i == 0) s << r[i];
    if (i > 0) s << 'X';
    if (i > 1) s << '^' << i;
  }
  if (!any) s << '0';
  return s;
}

}  // inline namespace edgetrack_ports
