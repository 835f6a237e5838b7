// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_bignum.h: signed integers of any size, with +Infinity and
/// -Infinity, upstream's constructors (every integer type, float, double, long double, and
/// strings in decimal, exponential "123e5", hexadecimal "0x1aF", octal "0123" or "+Inf" /
/// "-Infinity"), its conversions, arithmetic (division truncates, the remainder takes the
/// dividend's sign), shifts on the magnitude and comparisons. Upstream's infinity rules:
/// x / 0 and Inf * x are infinite, x / Inf is 0, x % Inf is x, Inf % x and x % 0 are 0;
/// integer conversions of an infinity give 0 and floating ones give +-infinity. The digits
/// are 16-bit, least significant first, as upstream's; upstream's Knuth helper functions
/// (add, subtract, divide, normalize...) are internal here, not declared.
#pragma once

#ifdef vnl_bignum_h_
#error "edgetrack's drop-in vnl/vnl_bignum.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

inline namespace edgetrack_ports {

class vnl_bignum {
 public:
  using Counter = unsigned short;
  using Data = unsigned short;

  vnl_bignum() = default;
  /// Any integer type, its whole range (LONG_MIN and unsigned long long's max included).
  template <typename T, typename = std::enable_if_t<std::is_integral<T>::value>>
  vnl_bignum(T arg) {  // NOLINT(google-explicit-constructor): upstream's implicit conversion
    using U = std::make_unsigned_t<T>;
    U magnitude = static_cast<U>(arg);
    if constexpr (std::is_signed<T>::value) {
      if (arg < 0) magnitude = static_cast<U>(U(0) - magnitude), sign_ = -1;  // exact for the lowest value too
    }
    // Two 8-bit shifts: one 16-bit shift of a 16-bit type would be undefined.
    for (; magnitude != 0; magnitude = static_cast<U>(magnitude >> 8 >> 8)) {
      data_.push_back(static_cast<Data>(magnitude & 0xFFFFu));
    }
  }
  /// The integer part (truncated toward zero); infinities and NaN give an infinity.
  vnl_bignum(float);        // NOLINT(google-explicit-constructor)
  vnl_bignum(double);       // NOLINT(google-explicit-constructor)
  vnl_bignum(long double);  // NOLINT(google-explicit-constructor)
  /// Parses one of the forms above, after leading white space; anything else gives 0 and a
  /// message on std::cerr, as upstream.
  vnl_bignum(const char*);  // NOLINT(google-explicit-constructor)

  /// Wrapping conversions to the integer types (the low bits, then the sign).
  operator short() const;        // NOLINT(google-explicit-constructor)
  operator int() const;          // NOLINT(google-explicit-constructor)
  operator long() const;         // NOLINT(google-explicit-constructor)
  operator float() const;        // NOLINT(google-explicit-constructor)
  operator double() const;       // NOLINT(google-explicit-constructor)
  operator long double() const;  // NOLINT(google-explicit-constructor)

  vnl_bignum operator-() const;
  vnl_bignum operator+() const { return *this; }

  /// Shifts of the magnitude; a negative count shifts the other way.
  vnl_bignum operator<<(int l) const;
  vnl_bignum operator>>(int l) const;
  vnl_bignum operator+(const vnl_bignum& r) const;
  vnl_bignum& operator+=(const vnl_bignum& r) { return *this = *this + r; }
  vnl_bignum& operator-=(const vnl_bignum& r) { return *this = *this + (-r); }
  vnl_bignum& operator*=(const vnl_bignum& r);
  vnl_bignum& operator/=(const vnl_bignum& r);
  vnl_bignum& operator%=(const vnl_bignum& r);
  vnl_bignum& operator<<=(int l) { return *this = *this << l; }
  vnl_bignum& operator>>=(int l) { return *this = *this >> l; }
  /// An infinity stays what it is.
  vnl_bignum& operator++();
  vnl_bignum& operator--();
  vnl_bignum operator++(int) {
    const vnl_bignum before = *this;
    ++*this;
    return before;
  }
  vnl_bignum operator--(int) {
    const vnl_bignum before = *this;
    --*this;
    return before;
  }

  bool operator==(const vnl_bignum& r) const { return sign_ == r.sign_ && data_ == r.data_; }
  bool operator<(const vnl_bignum& r) const;
  bool operator!=(const vnl_bignum& r) const { return !(*this == r); }
  bool operator>(const vnl_bignum& r) const { return r < *this; }
  bool operator<=(const vnl_bignum& r) const { return !(r < *this); }
  bool operator>=(const vnl_bignum& r) const { return !(*this < r); }
  bool operator==(long r) const { return *this == vnl_bignum(r); }
  bool operator!=(long r) const { return !(*this == r); }
  bool operator<(long r) const { return *this < vnl_bignum(r); }
  bool operator>(long r) const { return vnl_bignum(r) < *this; }
  bool operator<=(long r) const { return !(*this > r); }
  bool operator>=(long r) const { return !(*this < r); }
  bool operator==(int r) const { return *this == long(r); }
  bool operator!=(int r) const { return *this != long(r); }
  bool operator<(int r) const { return *this < long(r); }
  bool operator>(int r) const { return *this > long(r); }
  bool operator<=(int r) const { return *this <= long(r); }
  bool operator>=(int r) const { return *this >= long(r); }
  /// Compared as doubles, as upstream.
  bool operator==(double r) const { return double(*this) == r; }
  bool operator!=(double r) const { return double(*this) != r; }
  bool operator<(double r) const { return double(*this) < r; }
  bool operator>(double r) const { return double(*this) > r; }
  bool operator<=(double r) const { return double(*this) <= r; }
  bool operator>=(double r) const { return double(*this) >= r; }

  vnl_bignum abs() const { return sign_ < 0 ? -*this : *this; }
  bool is_infinity() const { return data_.size() == 1 && data_[0] == 0; }
  bool is_plus_infinity() const { return is_infinity() && sign_ == 1; }
  bool is_minus_infinity() const { return is_infinity() && sign_ == -1; }

  /// The sign, the 16-bit digits in hexadecimal and the value, for debugging.
  void dump(std::ostream& os) const;
  void dump() const;

  friend std::ostream& operator<<(std::ostream& s, const vnl_bignum& r);
  friend std::istream& operator>>(std::istream& s, vnl_bignum& r);
  friend std::string& vnl_bignum_to_string(std::string& s, const vnl_bignum& b);
  friend vnl_bignum& vnl_bignum_from_string(vnl_bignum& b, const std::string& s);

 private:
  using Digits = std::vector<Data>;
  static vnl_bignum infinity(int sign);
  /// sign * magnitude; zero digits at the top are dropped (a parsed "007").
  static vnl_bignum from_magnitude(Digits magnitude, int sign);
  template <class F>
  F to_floating() const;
  template <class F>
  void from_floating(F value);
  template <class I>
  I to_integer() const;
  /// Parses the whole of s (after white space); false when it is none of the forms.
  bool parse(const char* s);
  void normalize_zero();

  int sign_ = 1;  // +1 or -1; +1 for zero
  Digits data_;   // no leading zero digit, empty for 0; {0} is an infinity (upstream's encoding)
};

/// The decimal digits of b ("-" first when negative; "Inf" / "-Inf" for an infinity).
std::string& vnl_bignum_to_string(std::string& s, const vnl_bignum& b);
/// Reads a decimal integer or an infinity from s into b.
vnl_bignum& vnl_bignum_from_string(vnl_bignum& b, const std::string& s);

inline vnl_bignum operator+(const vnl_bignum& r1, long r2) { return r1 + vnl_bignum(r2); }
inline vnl_bignum operator+(const vnl_bignum& r1, int r2) { return r1 + long(r2); }
inline vnl_bignum operator+(const vnl_bignum& r1, double r2) { return r1 + vnl_bignum(r2); }
inline vnl_bignum operator+(long r2, const vnl_bignum& r1) { return r1 + r2; }
inline vnl_bignum operator+(int r2, const vnl_bignum& r1) { return r1 + r2; }
inline vnl_bignum operator+(double r2, const vnl_bignum& r1) { return r1 + r2; }
inline vnl_bignum operator-(const vnl_bignum& r1, const vnl_bignum& r2) { return r1 + (-r2); }
inline vnl_bignum operator-(const vnl_bignum& r1, long r2) { return r1 - vnl_bignum(r2); }
inline vnl_bignum operator-(const vnl_bignum& r1, int r2) { return r1 - long(r2); }
inline vnl_bignum operator-(const vnl_bignum& r1, double r2) { return r1 + vnl_bignum(-r2); }
inline vnl_bignum operator-(long r2, const vnl_bignum& r1) { return vnl_bignum(r2) - r1; }
inline vnl_bignum operator-(int r2, const vnl_bignum& r1) { return vnl_bignum(r2) - r1; }
inline vnl_bignum operator-(double r2, const vnl_bignum& r1) { return vnl_bignum(r2) - r1; }
inline vnl_bignum operator*(const vnl_bignum& r1, const vnl_bignum& r2) { return vnl_bignum(r1) *= r2; }
inline vnl_bignum operator*(const vnl_bignum& r1, long r2) { return vnl_bignum(r1) *= vnl_bignum(r2); }
inline vnl_bignum operator*(const vnl_bignum& r1, int r2) { return r1 * long(r2); }
inline vnl_bignum operator*(const vnl_bignum& r1, double r2) { return vnl_bignum(r1) *= vnl_bignum(r2); }
inline vnl_bignum operator*(long r2, const vnl_bignum& r1) { return r1 * r2; }
inline vnl_bignum operator*(int r2, const vnl_bignum& r1) { return r1 * long(r2); }
inline vnl_bignum operator*(double r2, const vnl_bignum& r1) { return r1 * r2; }
inline vnl_bignum operator/(const vnl_bignum& r1, const vnl_bignum& r2) { return vnl_bignum(r1) /= r2; }
inline vnl_bignum operator/(const vnl_bignum& r1, long r2) { return vnl_bignum(r1) /= vnl_bignum(r2); }
inline vnl_bignum operator/(const vnl_bignum& r1, int r2) { return r1 / long(r2); }
inline vnl_bignum operator/(const vnl_bignum& r1, double r2) { return vnl_bignum(r1) /= vnl_bignum(r2); }
inline vnl_bignum operator/(long r1, const vnl_bignum& r2) { return vnl_bignum(r1) /= r2; }
inline vnl_bignum operator/(int r1, const vnl_bignum& r2) { return vnl_bignum(r1) /= r2; }
inline vnl_bignum operator/(double r1, const vnl_bignum& r2) { return vnl_bignum(r1) /= r2; }
inline vnl_bignum operator%(const vnl_bignum& r1, const vnl_bignum& r2) { return vnl_bignum(r1) %= r2; }
inline vnl_bignum operator%(const vnl_bignum& r1, long r2) { return vnl_bignum(r1) %= vnl_bignum(r2); }
inline vnl_bignum operator%(const vnl_bignum& r1, int r2) { return r1 % long(r2); }
inline vnl_bignum operator%(long r1, const vnl_bignum& r2) { return vnl_bignum(r1) %= r2; }
inline vnl_bignum operator%(int r1, const vnl_bignum& r2) { return vnl_bignum(r1) %= r2; }

inline bool operator==(long r1, const vnl_bignum& r2) { return r2 == r1; }
inline bool operator!=(long r1, const vnl_bignum& r2) { return r2 != r1; }
inline bool operator<(long r1, const vnl_bignum& r2) { return r2 > r1; }
inline bool operator>(long r1, const vnl_bignum& r2) { return r2 < r1; }
inline bool operator<=(long r1, const vnl_bignum& r2) { return r2 >= r1; }
inline bool operator>=(long r1, const vnl_bignum& r2) { return r2 <= r1; }

namespace vnl_math {
inline vnl_bignum abs(const vnl_bignum& x) { return x.abs(); }
inline vnl_bignum squared_magnitude(const vnl_bignum& x) { return x * x; }
inline vnl_bignum sqr(const vnl_bignum& x) { return x * x; }
inline bool isnan(const vnl_bignum&) { return false; }
inline bool isfinite(const vnl_bignum& x) { return !x.is_infinity(); }
}  // namespace vnl_math

}  // inline namespace edgetrack_ports
