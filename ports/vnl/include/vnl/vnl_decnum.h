// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_decnum.h: numbers of any size in decimal, a sign ('+', '-', or
/// ' ' for zero), a mantissa of decimal digits without leading zero ("" for zero) and an
/// exponent: value = sign mantissa * 10^exp. Also +Inf, -Inf (mantissa "Inf") and NaN
/// ("NaN"). The arithmetic is upstream's, on mantissas: a sum or difference has the smaller
/// exponent; a product adds exponents; / and % are integer operations on the mantissas
/// (42e-3 / 30e-4 is 1e1 and 42e-3 % 30e-4 is 12e-3, while 42e-3 / 3e-3 is 14), the quotient
/// truncated and the remainder with the dividend's sign and exponent. Special values:
/// 1/0 = +Inf, 0/0 = NaN, 1/Inf = 0, x % 0 = x, x % Inf = NaN, NaN op x = NaN; NaN equals
/// nothing. Integer conversions truncate, wrap on overflow and map +-Inf to the int range.
/// Unlike upstream, parsing drops leading zeros after a decimal point too ("0.05" is 5e-2,
/// "0.00" is zero) and the double constructor maps infinities and NaN to Inf and NaN.
#pragma once

#ifdef vnl_decnum_h_
#error "edgetrack's drop-in vnl/vnl_decnum.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>
#include <string>
#include <type_traits>
#include <utility>

inline namespace edgetrack_ports {

class vnl_decnum {
  /// The operand types upstream overloads each operator for, besides vnl_decnum.
  template <class R>
  static constexpr bool is_operand =
      !std::is_same<R, vnl_decnum>::value &&
      (std::is_arithmetic<R>::value || std::is_convertible<const R&, std::string>::value);
  template <class R>
  using if_operand = std::enable_if_t<is_operand<R>, int>;

 public:
  std::string data() const { return data_; }
  char sign() const { return sign_; }
  long exp() const { return exp_; }

  vnl_decnum() = default;
  /// Parses [sign] digits [. digits] [e [sign] digits], "Inf..." or "NaN" after white space,
  /// stopping at the first character that does not fit (so no digits at all give zero).
  vnl_decnum(const std::string& r);                          // NOLINT(google-explicit-constructor)
  vnl_decnum(const char* r) : vnl_decnum(std::string(r)) {}  // NOLINT(google-explicit-constructor)
  explicit vnl_decnum(unsigned long r);
  explicit vnl_decnum(long r);
  explicit vnl_decnum(unsigned int r) : vnl_decnum(static_cast<unsigned long>(r)) {}
  explicit vnl_decnum(int r) : vnl_decnum(static_cast<long>(r)) {}
  /// From the double's default stream text (6 significant digits), as upstream: integers
  /// below 10^6 are exact, other values are not guaranteed.
  vnl_decnum(double r);  // NOLINT(google-explicit-constructor)

  /// The value as text: "0", "-1234", "12e-3", "Inf", "-Inf" or "NaN".
  operator std::string() const;    // NOLINT(google-explicit-constructor)
  operator long() const;           // NOLINT(google-explicit-constructor)
  operator unsigned long() const;  // NOLINT(google-explicit-constructor): drops the sign
  operator int() const;            // NOLINT(google-explicit-constructor)
  operator unsigned int() const;   // NOLINT(google-explicit-constructor): drops the sign

  vnl_decnum operator+() const { return *this; }
  vnl_decnum operator-() const { return sign_ == ' ' ? *this : vnl_decnum(sign_ == '-' ? '+' : '-', data_, exp_); }
  /// Digit shifts: the exponent moves by r (nothing happens to zero).
  vnl_decnum operator<<(long r) const { return sign_ == ' ' ? *this : vnl_decnum(sign_, data_, exp_ + r); }
  vnl_decnum operator<<(int r) const { return *this << long(r); }
  vnl_decnum operator>>(long r) const { return *this << -r; }
  vnl_decnum operator>>(int r) const { return *this << -long(r); }
  vnl_decnum& operator<<=(long r) { return *this = *this << r; }
  vnl_decnum& operator<<=(int r) { return *this = *this << r; }
  vnl_decnum& operator>>=(long r) { return *this = *this >> r; }
  vnl_decnum& operator>>=(int r) { return *this = *this >> r; }

  /// Moves trailing zeros of the mantissa into the exponent.
  vnl_decnum& compactify();
  /// Writes an integer without exponent (as upstream, by adding and subtracting 1).
  vnl_decnum& expand() { return *this = (*this + 1L) - 1L; }

  vnl_decnum operator+(const vnl_decnum& r) const;
  vnl_decnum operator-(const vnl_decnum& r) const { return *this + (-r); }
  vnl_decnum operator*(const vnl_decnum& r) const;
  vnl_decnum operator/(const vnl_decnum& r) const;
  vnl_decnum operator%(const vnl_decnum& r) const;
  vnl_decnum& operator+=(const vnl_decnum& r) { return *this = *this + r; }
  vnl_decnum& operator-=(const vnl_decnum& r) { return *this = *this - r; }
  vnl_decnum& operator*=(const vnl_decnum& r) { return *this = *this * r; }
  vnl_decnum& operator/=(const vnl_decnum& r) { return *this = *this / r; }
  vnl_decnum& operator%=(const vnl_decnum& r) { return *this = *this % r; }

  // Upstream's overloads for strings, the integer types and double on the right.
  template <class R, if_operand<R> = 0>
  vnl_decnum& operator=(const R& r) {
    return *this = vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum operator+(const R& r) const {
    return *this + vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum operator-(const R& r) const {
    return *this - vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum operator*(const R& r) const {
    return *this * vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum operator/(const R& r) const {
    return *this / vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum operator%(const R& r) const {
    return *this % vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum& operator+=(const R& r) {
    return *this += vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum& operator-=(const R& r) {
    return *this -= vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum& operator*=(const R& r) {
    return *this *= vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum& operator/=(const R& r) {
    return *this /= vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  vnl_decnum& operator%=(const R& r) {
    return *this %= vnl_decnum(r);
  }

  vnl_decnum& operator++() { return *this = *this + 1L; }
  vnl_decnum& operator--() { return *this = *this - 1L; }
  vnl_decnum operator++(int) {
    const vnl_decnum before = *this;
    ++*this;
    return before;
  }
  vnl_decnum operator--(int) {
    const vnl_decnum before = *this;
    --*this;
    return before;
  }

  /// Numeric comparisons (1000 == 1e3); NaN compares false with everything.
  bool operator==(const vnl_decnum& r) const;
  bool operator<(const vnl_decnum& r) const;
  bool operator!=(const vnl_decnum& r) const { return !(*this == r); }
  bool operator>(const vnl_decnum& r) const { return r < *this; }
  bool operator<=(const vnl_decnum& r) const { return !(r < *this); }
  bool operator>=(const vnl_decnum& r) const { return !(*this < r); }
  template <class R, if_operand<R> = 0>
  bool operator==(const R& r) const {
    return *this == vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  bool operator!=(const R& r) const {
    return *this != vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  bool operator<(const R& r) const {
    return *this < vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  bool operator>(const R& r) const {
    return *this > vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  bool operator<=(const R& r) const {
    return *this <= vnl_decnum(r);
  }
  template <class R, if_operand<R> = 0>
  bool operator>=(const R& r) const {
    return *this >= vnl_decnum(r);
  }

  vnl_decnum abs() const { return sign_ == '-' ? -*this : *this; }
  /// The integer part (toward zero).
  vnl_decnum trunc() const;
  /// The integer away from zero, for non-integers.
  vnl_decnum roundup() const { return *this == trunc() ? *this : sign_ == '-' ? trunc() - 1L : trunc() + 1L; }
  vnl_decnum floor() const { return sign_ == '-' ? roundup() : trunc(); }
  vnl_decnum ceil() const { return sign_ == '-' ? trunc() : roundup(); }
  vnl_decnum pow(unsigned long p) const {
    return p == 0 ? vnl_decnum(1L) : p == 1 ? *this : pow(p / 2) * pow((p + 1) / 2);
  }

 private:
  vnl_decnum(char s, std::string d, long e) : sign_(s), data_(std::move(d)), exp_(e) {}
  bool is_nan() const { return data_ == "NaN"; }
  bool is_inf() const { return data_ == "Inf"; }
  /// The mantissa with zeros appended to reach exponent `exp` (<= exp_).
  std::string aligned_to(long exp) const { return data_ + std::string(static_cast<std::size_t>(exp_ - exp), '0'); }
  template <class U>
  U to_unsigned() const;

  char sign_ = ' ';
  std::string data_;
  long exp_ = 0;
};

std::ostream& operator<<(std::ostream& s, const vnl_decnum& r);
/// Reads one number (as the string constructor); an empty line or the end gives zero.
std::istream& operator>>(std::istream& s, vnl_decnum& r);

inline vnl_decnum ceil(const vnl_decnum& x) { return x.ceil(); }
inline vnl_decnum floor(const vnl_decnum& x) { return x.floor(); }
inline vnl_decnum pow(const vnl_decnum& x, unsigned long p) { return x.pow(p); }

namespace vnl_math {
inline vnl_decnum abs(const vnl_decnum& x) { return x.abs(); }
inline vnl_decnum sqr(const vnl_decnum& x) { return x * x; }
inline vnl_decnum cube(const vnl_decnum& x) { return x * x * x; }
inline vnl_decnum squared_magnitude(const vnl_decnum& x) { return x * x; }
inline bool isnan(const vnl_decnum& x) { return x.data() == "NaN"; }
inline bool isfinite(const vnl_decnum& x) { return x.data() != "Inf" && x.data() != "NaN"; }
inline vnl_decnum max(const vnl_decnum& x, const vnl_decnum& y) { return x < y ? y : x; }
inline vnl_decnum min(const vnl_decnum& x, const vnl_decnum& y) { return x < y ? x : y; }
inline int sgn(const vnl_decnum& x) { return x.sign() == ' ' ? 0 : x.sign() == '+' ? 1 : -1; }
inline int sgn0(const vnl_decnum& x) { return x.sign() == '-' ? -1 : 1; }
}  // namespace vnl_math

}  // inline namespace edgetrack_ports
