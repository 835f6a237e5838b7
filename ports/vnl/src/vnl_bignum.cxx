// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_bignum.h"

#include <cmath>
#include <iostream>
#include <utility>

inline namespace edgetrack_ports {

namespace {
using Data = vnl_bignum::Data;
using Digits = std::vector<Data>;
constexpr std::uint32_t kBase = 0x10000;

void trim(Digits& a) {
  while (!a.empty() && a.back() == 0) a.pop_back();
}

/// -1, 0 or 1 as |a| <, = or > |b| (both trimmed).
int magnitude_compare(const Digits& a, const Digits& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;) {
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  }
  return 0;
}

Digits magnitude_add(const Digits& a, const Digits& b) {
  const Digits& longer = a.size() >= b.size() ? a : b;
  const Digits& shorter = a.size() >= b.size() ? b : a;
  Digits sum(longer.size() + 1, 0);
  std::uint32_t carry = 0;
  for (std::size_t i = 0; i < longer.size(); ++i) {
    carry += longer[i] + (i < shorter.size() ? shorter[i] : 0u);
    sum[i] = static_cast<Data>(carry & 0xFFFFu);
    carry >>= 16;
  }
  sum.back() = static_cast<Data>(carry);
  trim(sum);
  return sum;
}

/// |a| - |b| for |a| >= |b|.
Digits magnitude_subtract(const Digits& a, const Digits& b) {
  Digits difference(a);
  std::int32_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int32_t d = std::int32_t{a[i]} - (i < b.size() ? std::int32_t{b[i]} : 0) - borrow;
    borrow = d < 0;
    difference[i] = static_cast<Data>(d + (borrow ? std::int32_t{kBase} : 0));
  }
  trim(difference);
  return difference;
}

Digits magnitude_multiply(const Digits& a, const Digits& b) {
  if (a.empty() || b.empty()) return {};
  Digits product(a.size() + b.size(), 0);
  for (std::size_t j = 0; j < b.size(); ++j) {
    std::uint32_t carry = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      carry += std::uint32_t{a[i]} * b[j] + product[i + j];
      product[i + j] = static_cast<Data>(carry & 0xFFFFu);
      carry >>= 16;
    }
    product[j + a.size()] = static_cast<Data>(carry);
  }
  trim(product);
  return product;
}

/// a / d and a % d for one nonzero digit d.
Digits magnitude_divide_small(const Digits& a, Data d, Data& remainder) {
  Digits quotient(a.size(), 0);
  std::uint32_t rest = 0;
  for (std::size_t i = a.size(); i-- > 0;) {
    rest = (rest << 16) | a[i];
    quotient[i] = static_cast<Data>(rest / d);
    rest %= d;
  }
  remainder = static_cast<Data>(rest);
  trim(quotient);
  return quotient;
}

Digits shift_left(const Digits& a, unsigned bits) {
  if (a.empty()) return a;
  Digits shifted(a.size() + bits / 16 + 1, 0);
  const unsigned digit_shift = bits / 16, bit_shift = bits % 16;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::uint32_t moved = std::uint32_t{a[i]} << bit_shift;
    shifted[i + digit_shift] = static_cast<Data>(shifted[i + digit_shift] | (moved & 0xFFFFu));
    shifted[i + digit_shift + 1] = static_cast<Data>(moved >> 16);
  }
  trim(shifted);
  return shifted;
}

Digits shift_right(const Digits& a, unsigned bits) {
  const std::size_t digit_shift = bits / 16;
  if (digit_shift >= a.size()) return {};
  const unsigned bit_shift = bits % 16;
  Digits shifted(a.size() - digit_shift, 0);
  for (std::size_t i = 0; i < shifted.size(); ++i) {
    std::uint32_t window = a[i + digit_shift];
    if (i + digit_shift + 1 < a.size()) window |= std::uint32_t{a[i + digit_shift + 1]} << 16;
    shifted[i] = static_cast<Data>((window >> bit_shift) & 0xFFFFu);
  }
  trim(shifted);
  return shifted;
}

/// a / b and a % b (b nonzero): one digit by short division, longer ones bit by bit.
std::pair<Digits, Digits> magnitude_divide(const Digits& a, const Digits& b) {
  if (magnitude_compare(a, b) < 0) return {Digits{}, a};
  if (b.size() == 1) {
    Data r = 0;
    Digits q = magnitude_divide_small(a, b[0], r);
    return {q, r ? Digits{r} : Digits{}};
  }
  Digits quotient(a.size(), 0), rest;
  for (std::size_t bit = a.size() * 16; bit-- > 0;) {
    rest = shift_left(rest, 1);
    if ((a[bit / 16] >> (bit % 16)) & 1u) {
      if (rest.empty()) rest.push_back(0);
      rest[0] = static_cast<Data>(rest[0] | 1u);
    }
    if (magnitude_compare(rest, b) >= 0) {
      rest = magnitude_subtract(rest, b);
      quotient[bit / 16] = static_cast<Data>(quotient[bit / 16] | (1u << (bit % 16)));
    }
  }
  trim(quotient);
  return {quotient, rest};
}

/// The decimal digits of a magnitude, most significant first ("0" for zero).
std::string decimal_digits(Digits a) {
  std::string reversed;
  do {
    Data digit = 0;
    a = magnitude_divide_small(a, 10, digit);
    reversed.push_back(static_cast<char>('0' + digit));
  } while (!a.empty());
  return std::string(reversed.rbegin(), reversed.rend());
}

}  // namespace

vnl_bignum vnl_bignum::infinity(int sign) {
  vnl_bignum b;
  b.data_ = Digits{0};
  b.sign_ = sign < 0 ? -1 : 1;
  return b;
}

vnl_bignum vnl_bignum::from_magnitude(Digits magnitude, int sign) {
  vnl_bignum b;
  trim(magnitude);
  b.data_ = std::move(magnitude);
  b.sign_ = sign < 0 ? -1 : 1;
  b.normalize_zero();
  return b;
}

void vnl_bignum::normalize_zero() {
  if (data_.empty()) sign_ = 1;
}

template <class F>
void vnl_bignum::from_floating(F value) {
  if (!std::isfinite(value)) {
    *this = infinity(value < 0 ? -1 : 1);
    return;
  }
  sign_ = value < 0 ? -1 : 1;
  // fmod by and division by 2^16 are exact, so every digit of the integer part is.
  for (F d = std::floor(std::fabs(value)); d >= F(1); d = std::floor(d / F(kBase))) {
    data_.push_back(static_cast<Data>(std::fmod(d, F(kBase))));
  }
  normalize_zero();
}

vnl_bignum::vnl_bignum(float value) { from_floating(value); }
vnl_bignum::vnl_bignum(double value) { from_floating(value); }
vnl_bignum::vnl_bignum(long double value) { from_floating(value); }

vnl_bignum::vnl_bignum(const char* s) {
  if (!parse(s)) std::cerr << "Cannot convert string " << s << " to vnl_bignum\n";
}

template <class F>
F vnl_bignum::to_floating() const {
  if (is_infinity()) return sign_ * std::numeric_limits<F>::infinity();
  F value = 0;
  for (std::size_t i = data_.size(); i-- > 0;) value = value * F(kBase) + F(data_[i]);
  return sign_ < 0 ? -value : value;
}

template <class I>
I vnl_bignum::to_integer() const {
  using U = std::make_unsigned_t<I>;
  U value = 0;
  if (!is_infinity()) {
    for (std::size_t i = data_.size(); i-- > 0;) value = static_cast<U>((value << 8 << 8) | data_[i]);
  }
  if (sign_ < 0) value = static_cast<U>(U(0) - value);
  return static_cast<I>(value);
}

vnl_bignum::operator short() const { return static_cast<short>(to_integer<int>()); }
vnl_bignum::operator int() const { return to_integer<int>(); }
vnl_bignum::operator long() const { return to_integer<long>(); }
vnl_bignum::operator float() const { return to_floating<float>(); }
vnl_bignum::operator double() const { return to_floating<double>(); }
vnl_bignum::operator long double() const { return to_floating<long double>(); }

vnl_bignum vnl_bignum::operator-() const {
  vnl_bignum negated(*this);
  negated.sign_ = -sign_;
  negated.normalize_zero();
  return negated;
}

vnl_bignum vnl_bignum::operator+(const vnl_bignum& b) const {
  if (b.is_infinity()) return b;  // upstream's rule, also for +Inf + -Inf
  if (is_infinity()) return *this;
  if (sign_ == b.sign_) return from_magnitude(magnitude_add(data_, b.data_), sign_);
  const int order = magnitude_compare(data_, b.data_);
  if (order == 0) return vnl_bignum();
  return order > 0 ? from_magnitude(magnitude_subtract(data_, b.data_), sign_)
                   : from_magnitude(magnitude_subtract(b.data_, data_), b.sign_);
}

vnl_bignum& vnl_bignum::operator*=(const vnl_bignum& b) {
  if (b.is_infinity()) return *this = sign_ < 0 ? -b : b;
  if (is_infinity()) return *this = b.sign_ < 0 ? -*this : *this;
  return *this = from_magnitude(magnitude_multiply(data_, b.data_), sign_ * b.sign_);
}

vnl_bignum& vnl_bignum::operator/=(const vnl_bignum& b) {
  if (b.is_infinity()) return *this = vnl_bignum();
  if (is_infinity()) return *this = b.sign_ < 0 ? -*this : *this;
  if (b.data_.empty()) return *this = infinity(sign_);
  return *this = from_magnitude(magnitude_divide(data_, b.data_).first, sign_ * b.sign_);
}

vnl_bignum& vnl_bignum::operator%=(const vnl_bignum& b) {
  if (b.is_infinity()) return *this;
  if (is_infinity() || b.data_.empty()) return *this = vnl_bignum();
  return *this = from_magnitude(magnitude_divide(data_, b.data_).second, sign_);
}

vnl_bignum vnl_bignum::operator<<(int l) const {
  if (is_infinity() || l == 0 || data_.empty()) return *this;
  const unsigned bits = l < 0 ? 0u - static_cast<unsigned>(l) : static_cast<unsigned>(l);
  return from_magnitude(l > 0 ? shift_left(data_, bits) : shift_right(data_, bits), sign_);
}

vnl_bignum vnl_bignum::operator>>(int l) const {
  if (is_infinity() || l == 0 || data_.empty()) return *this;
  return *this << -l;
}

vnl_bignum& vnl_bignum::operator++() {
  if (!is_infinity()) *this = *this + vnl_bignum(1);
  return *this;
}

vnl_bignum& vnl_bignum::operator--() {
  if (!is_infinity()) *this = *this + vnl_bignum(-1);
  return *this;
}

bool vnl_bignum::operator<(const vnl_bignum& r) const {
  if (is_infinity() || r.is_infinity()) {
    if (*this == r) return false;
    return is_minus_infinity() || r.is_plus_infinity();
  }
  if (sign_ != r.sign_) return sign_ < r.sign_;
  const int order = magnitude_compare(data_, r.data_);
  return sign_ > 0 ? order < 0 : order > 0;
}

void vnl_bignum::dump(std::ostream& os) const {
  os << "{count=" << data_.size() << ", sign=" << sign_ << ", value=" << *this << ", {" << std::hex;
  for (std::size_t i = data_.size(); i-- > 0;) os << data_[i] << (i ? "," : "");
  os << std::dec << "}}\n";
}

void vnl_bignum::dump() const { dump(std::cout); }

std::ostream& operator<<(std::ostream& s, const vnl_bignum& r) {
  std::string text;
  return s << vnl_bignum_to_string(text, r);
}

std::string& vnl_bignum_to_string(std::string& s, const vnl_bignum& b) {
  s = b.sign_ < 0 ? "-" : "";
  s += b.is_infinity() ? "Inf" : decimal_digits(b.data_);
  return s;
}

}  // inline namespace edgetrack_ports
