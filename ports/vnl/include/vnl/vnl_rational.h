// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_rational.h: exact rational numbers num/den with 64-bit integer
/// parts, always in lowest terms with den > 0; 1/0 and -1/0 are +-infinity (0/0 is not
/// allowed). A double converts by its continued fraction, cut as upstream cuts it (remainder
/// under 1e-6, terms under 1e9; magnitudes from 1e9 are infinite). As upstream, a product or sum that
/// would overflow 64 bits gives the nearest representable approximation instead.
#pragma once

#ifdef vnl_rational_h_
#error "edgetrack's drop-in vnl/vnl_rational.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdint>
#include <iosfwd>
#include <type_traits>

inline namespace edgetrack_ports {

class vnl_rational {
 public:
  using int_type = std::int64_t;

  vnl_rational() = default;
  template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
  vnl_rational(T num) : num_(static_cast<int_type>(num)), den_(1) {}
  vnl_rational(int_type num, int_type den) : num_(num), den_(den) { normalize(); }
  /// The continued-fraction approximation of d (upstream's cut: 0.42857142857 is 3/7).
  vnl_rational(double d);
  vnl_rational(float f) : vnl_rational(static_cast<double>(f)) {}

  int_type numerator() const { return num_; }
  int_type denominator() const { return den_; }
  void set(int_type num, int_type den) {
    num_ = num, den_ = den;
    normalize();
  }

  bool operator==(const vnl_rational& rhs) const { return num_ == rhs.num_ && den_ == rhs.den_; }
  bool operator!=(const vnl_rational& rhs) const { return !(*this == rhs); }
  vnl_rational operator-() const { return vnl_rational(-num_, den_); }
  vnl_rational operator+() const { return *this; }
  bool operator!() const { return num_ == 0; }
  vnl_rational abs() const { return vnl_rational(num_ < 0 ? -num_ : num_, den_); }
  /// 1 / this; 0 becomes +infinity.
  vnl_rational& invert();

  vnl_rational& operator+=(const vnl_rational& r);
  vnl_rational& operator-=(const vnl_rational& r);
  vnl_rational& operator*=(const vnl_rational& r);
  vnl_rational& operator/=(const vnl_rational& r);
  /// The remainder of this / r with the sign of this.
  vnl_rational& operator%=(const vnl_rational& r);
  vnl_rational& operator++() { return *this += 1; }
  vnl_rational& operator--() { return *this -= 1; }
  vnl_rational operator++(int) {
    const vnl_rational old(*this);
    ++*this;
    return old;
  }
  vnl_rational operator--(int) {
    const vnl_rational old(*this);
    --*this;
    return old;
  }

  bool operator<(const vnl_rational& rhs) const;
  bool operator>(const vnl_rational& r) const { return r < *this; }
  bool operator<=(const vnl_rational& r) const { return !(r < *this); }
  bool operator>=(const vnl_rational& r) const { return !(*this < r); }

  /// Rounding to integers: toward zero, down, up, to nearest (halves away from zero).
  int_type truncate() const { return den_ == 0 ? num_ : num_ / den_; }
  int_type floor() const;
  int_type ceil() const;
  int_type round() const;
  explicit operator int_type() const { return truncate(); }
  explicit operator double() const { return static_cast<double>(num_) / static_cast<double>(den_); }
  explicit operator float() const { return static_cast<float>(static_cast<double>(*this)); }

  bool is_finite() const { return den_ != 0; }
  bool is_plus_inf() const { return den_ == 0 && num_ > 0; }
  bool is_minus_inf() const { return den_ == 0 && num_ < 0; }
  bool is_integral() const { return den_ == 1; }

  /// Greatest common divisor, non-negative (0 only for gcd(0, 0)).
  static int_type gcd(int_type l1, int_type l2);

 private:
  void normalize();

  int_type num_ = 0;
  int_type den_ = 1;
};

inline vnl_rational operator+(vnl_rational a, const vnl_rational& b) { return a += b; }
inline vnl_rational operator-(vnl_rational a, const vnl_rational& b) { return a -= b; }
inline vnl_rational operator*(vnl_rational a, const vnl_rational& b) { return a *= b; }
inline vnl_rational operator/(vnl_rational a, const vnl_rational& b) { return a /= b; }
inline vnl_rational operator%(vnl_rational a, const vnl_rational& b) { return a %= b; }

/// Comparisons with an integer on the left, as upstream's.
template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
bool operator==(T a, const vnl_rational& b) {
  return b == vnl_rational(a);
}
template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
bool operator!=(T a, const vnl_rational& b) {
  return b != vnl_rational(a);
}
template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
bool operator<(T a, const vnl_rational& b) {
  return b > vnl_rational(a);
}
template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
bool operator>(T a, const vnl_rational& b) {
  return b < vnl_rational(a);
}
template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
bool operator<=(T a, const vnl_rational& b) {
  return b >= vnl_rational(a);
}
template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
bool operator>=(T a, const vnl_rational& b) {
  return b <= vnl_rational(a);
}

/// The rounding members as free functions, as upstream's.
inline vnl_rational::int_type truncate(const vnl_rational& r) { return r.truncate(); }
inline vnl_rational::int_type floor(const vnl_rational& r) { return r.floor(); }
inline vnl_rational::int_type ceil(const vnl_rational& r) { return r.ceil(); }
inline vnl_rational::int_type round(const vnl_rational& r) { return r.round(); }

/// Prints num/den; reads two integers, num then den.
std::ostream& operator<<(std::ostream& s, const vnl_rational& r);
std::istream& operator>>(std::istream& s, vnl_rational& r);

namespace vnl_math {
inline vnl_rational abs(const vnl_rational& x) { return x.abs(); }
inline vnl_rational squared_magnitude(const vnl_rational& x) { return x * x; }
inline vnl_rational sqr(const vnl_rational& x) { return x * x; }
inline bool isnan(const vnl_rational&) { return false; }
inline bool isfinite(const vnl_rational& x) { return x.is_finite(); }
}  // namespace vnl_math

}  // inline namespace edgetrack_ports
