// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_decnum.h"

#include <cctype>
#include <cmath>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <vector>

inline namespace edgetrack_ports {

namespace {
// Mantissa arithmetic on strings of decimal digits without leading zeros ("" is zero).

void strip_leading_zeros(std::string& a) {
  const std::size_t first = a.find_first_not_of('0');
  a.erase(0, first == std::string::npos ? a.size() : first);
}

/// -1, 0 or 1 as a <, = or > b.
int digits_compare(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  const int c = a.compare(b);
  return c < 0 ? -1 : c > 0 ? 1 : 0;
}

std::string digits_add(const std::string& a, const std::string& b) {
  std::string sum;
  int carry = 0;
  for (std::size_t i = 0; i < a.size() || i < b.size() || carry; ++i) {
    const int d =
        carry + (i < a.size() ? a[a.size() - 1 - i] - '0' : 0) + (i < b.size() ? b[b.size() - 1 - i] - '0' : 0);
    sum.push_back(static_cast<char>('0' + d % 10));
    carry = d / 10;
  }
  return std::string(sum.rbegin(), sum.rend());
}

/// a - b for a >= b.
std::string digits_subtract(const std::string& a, const std::string& b) {
  std::string difference;
  int borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    int d = (a[a.size() - 1 - i] - '0') - borrow - (i < b.size() ? b[b.size() - 1 - i] - '0' : 0);
    borrow = d < 0;
    difference.push_back(static_cast<char>('0' + d + (borrow ? 10 : 0)));
  }
  std::string result(difference.rbegin(), difference.rend());
  strip_leading_zeros(result);
  return result;
}

std::string digits_multiply(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return "";
  std::vector<int> product(a.size() + b.size(), 0);  // least significant first
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j)
      product[i + j] += (a[a.size() - 1 - i] - '0') * (b[b.size() - 1 - j] - '0');
  }
  std::string result;
  int carry = 0;
  for (const int p : product) {
    const int d = p + carry;
    result.push_back(static_cast<char>('0' + d % 10));
    carry = d / 10;
  }
  std::string digits(result.rbegin(), result.rend());
  strip_leading_zeros(digits);
  return digits;
}

/// Long division: the quotient and remainder of a / b (b nonzero).
std::pair<std::string, std::string> digits_divide(const std::string& a, const std::string& b) {
  std::string quotient, rest;
  for (const char digit : a) {
    rest.push_back(digit);
    strip_leading_zeros(rest);
    char q = '0';
    while (digits_compare(rest, b) >= 0) rest = digits_subtract(rest, b), ++q;
    quotient.push_back(q);
  }
  strip_leading_zeros(quotient);
  return {quotient, rest};
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
}  // namespace

vnl_decnum::vnl_decnum(const std::string& r) : sign_('+') {
  const char* p = r.c_str();
  while (is_blank(*p)) ++p;
  if (*p == '-' || *p == '+') sign_ = *p++ == '-' ? '-' : '+';
  if (p[0] == 'I' && p[1] == 'n' && p[2] == 'f') {
    data_ = "Inf";
    return;
  }
  if (p[0] == 'N' && p[1] == 'a' && p[2] == 'N') {
    data_ = "NaN";
    return;
  }
  long fraction_digits = 0;
  for (; *p >= '0' && *p <= '9'; ++p) data_.push_back(*p);
  if (*p == '.') {
    for (++p; *p >= '0' && *p <= '9'; ++p) data_.push_back(*p), ++fraction_digits;
  }
  strip_leading_zeros(data_);
  if (data_.empty()) {
    sign_ = ' ';
    return;
  }
  if (*p == 'e') {
    ++p;
    const bool negative = *p == '-';
    if (*p == '-' || *p == '+') ++p;
    for (; *p >= '0' && *p <= '9'; ++p) exp_ = exp_ * 10 + (*p - '0');
    if (negative) exp_ = -exp_;
  }
  exp_ -= fraction_digits;
}

vnl_decnum::vnl_decnum(unsigned long r) : sign_(r == 0 ? ' ' : '+') {
  for (; r != 0; r /= 10) data_.insert(data_.begin(), static_cast<char>('0' + r % 10));
}

vnl_decnum::vnl_decnum(long r)
    : vnl_decnum(r < 0 ? 0UL - static_cast<unsigned long>(r) : static_cast<unsigned long>(r)) {
  if (r < 0) sign_ = '-';
}

vnl_decnum::vnl_decnum(double r) {
  if (std::isnan(r)) {
    *this = vnl_decnum("NaN");
  } else if (std::isinf(r)) {
    *this = vnl_decnum(r < 0 ? "-Inf" : "+Inf");
  } else {
    std::ostringstream os;
    os << r;
    *this = vnl_decnum(os.str());
  }
}

vnl_decnum::operator std::string() const {
  if (is_nan()) return "NaN";
  if (sign_ == ' ') return "0";
  std::string text = (sign_ == '-' ? "-" : "") + data_;
  if (exp_ != 0) text += "e" + std::to_string(exp_);
  return text;
}

template <class U>
U vnl_decnum::to_unsigned() const {
  U value = 0;
  const long integer_digits = static_cast<long>(data_.size()) + exp_;
  for (long i = 0; i < integer_digits; ++i) {
    value = static_cast<U>(value * 10u + (i < static_cast<long>(data_.size()) ? unsigned(data_[i] - '0') : 0u));
  }
  return value;
}

vnl_decnum::operator unsigned long() const {
  if (is_nan()) return 0;
  return is_inf() ? 0xffffffffUL : to_unsigned<unsigned long>();
}

vnl_decnum::operator unsigned int() const {
  if (is_nan()) return 0;
  return is_inf() ? 0xffffffffu : to_unsigned<unsigned int>();
}

vnl_decnum::operator long() const {
  if (is_nan()) return 0;
  if (is_inf()) return sign_ == '-' ? -0x7fffffffL - 1 : 0x7fffffffL;
  const unsigned long magnitude = to_unsigned<unsigned long>();
  return static_cast<long>(sign_ == '-' ? 0UL - magnitude : magnitude);
}

vnl_decnum::operator int() const {
  if (is_nan()) return 0;
  if (is_inf()) return sign_ == '-' ? -0x7fffffff - 1 : 0x7fffffff;
  const unsigned int magnitude = to_unsigned<unsigned int>();
  return static_cast<int>(sign_ == '-' ? 0u - magnitude : magnitude);
}

vnl_decnum& vnl_decnum::compactify() {
  if (sign_ == ' ' || is_inf() || is_nan()) {
    exp_ = 0;
    return *this;
  }
  const std::size_t kept = data_.find_last_not_of('0') + 1;
  exp_ += static_cast<long>(data_.size() - kept);
  data_.erase(kept);
  return *this;
}

bool vnl_decnum::operator==(const vnl_decnum& r) const {
  if (sign_ != r.sign_ || is_nan() || r.is_nan()) return false;
  if (is_inf() || r.is_inf()) return data_ == r.data_;
  if (sign_ == ' ') return true;
  const long exp = exp_ < r.exp_ ? exp_ : r.exp_;
  return aligned_to(exp) == r.aligned_to(exp);
}

bool vnl_decnum::operator<(const vnl_decnum& r) const {
  if (is_nan() || r.is_nan() || *this == r) return false;
  if (is_inf()) return sign_ == '-';
  if (r.is_inf()) return r.sign_ == '+';
  const int s = sign_ == '-' ? -1 : sign_ == ' ' ? 0 : 1, rs = r.sign_ == '-' ? -1 : r.sign_ == ' ' ? 0 : 1;
  if (s != rs) return s < rs;
  const long exp = exp_ < r.exp_ ? exp_ : r.exp_;
  const int order = digits_compare(aligned_to(exp), r.aligned_to(exp));
  return s > 0 ? order < 0 : order > 0;
}

vnl_decnum vnl_decnum::operator+(const vnl_decnum& r) const {
  if (is_nan()) return *this;
  if (r.is_nan()) return r;
  if (is_inf() && r.is_inf()) return sign_ == r.sign_ ? *this : vnl_decnum("NaN");
  if (is_inf() || r.sign_ == ' ') return *this;
  if (r.is_inf() || sign_ == ' ') return r;
  const long exp = exp_ < r.exp_ ? exp_ : r.exp_;  // the sum keeps every digit of both
  const std::string a = aligned_to(exp), b = r.aligned_to(exp);
  if (sign_ == r.sign_) return vnl_decnum(sign_, digits_add(a, b), exp);
  const int order = digits_compare(a, b);
  if (order == 0) return vnl_decnum(0L);
  return order > 0 ? vnl_decnum(sign_, digits_subtract(a, b), exp) : vnl_decnum(r.sign_, digits_subtract(b, a), exp);
}

vnl_decnum vnl_decnum::operator*(const vnl_decnum& r) const {
  if (is_nan()) return *this;
  if (r.is_nan()) return r;
  if (is_inf() || r.is_inf()) {
    if (sign_ == ' ' || r.sign_ == ' ') return vnl_decnum("NaN");
    return vnl_decnum(sign_ == r.sign_ ? "+Inf" : "-Inf");
  }
  if (sign_ == ' ' || r.sign_ == ' ') return vnl_decnum(0L);
  return vnl_decnum(sign_ == r.sign_ ? '+' : '-', digits_multiply(data_, r.data_), exp_ + r.exp_);
}

vnl_decnum vnl_decnum::operator/(const vnl_decnum& r) const {
  if (is_nan()) return *this;
  if (r.is_nan()) return r;
  if (is_inf() && r.is_inf()) return vnl_decnum("NaN");
  if (r.is_inf()) return vnl_decnum(0L);
  if (is_inf()) return vnl_decnum((sign_ == '-') == (r.sign_ == '-') ? "+Inf" : "-Inf");
  if (r.sign_ == ' ') return sign_ == ' ' ? vnl_decnum("NaN") : vnl_decnum(sign_ == '+' ? "+Inf" : "-Inf");
  if (r == 1L) return *this;
  if (*this == r) return vnl_decnum('+', "1", 0);
  const std::string quotient = digits_divide(data_, r.data_).first;
  if (quotient.empty()) return vnl_decnum(0L);
  return vnl_decnum((sign_ == '-') == (r.sign_ == '-') ? '+' : '-', quotient, exp_ - r.exp_);
}

vnl_decnum vnl_decnum::operator%(const vnl_decnum& r) const {
  if (r.sign_ == ' ' || is_nan()) return *this;
  if (r.is_nan()) return r;
  if (r.is_inf()) return vnl_decnum("NaN");
  if (is_inf()) return *this;
  if (r == 1L || *this == r) return vnl_decnum(0L);
  const std::string rest = digits_divide(data_, r.data_).second;
  return rest.empty() ? vnl_decnum(0L) : vnl_decnum(sign_, rest, exp_);
}

vnl_decnum vnl_decnum::trunc() const {
  if (exp_ >= 0 || is_inf() || is_nan()) return *this;
  const long integer_digits = static_cast<long>(data_.size()) + exp_;
  if (integer_digits <= 0) return vnl_decnum(0L);
  return vnl_decnum(sign_, data_.substr(0, static_cast<std::size_t>(integer_digits)), 0);
}

std::ostream& operator<<(std::ostream& s, const vnl_decnum& r) { return s << std::string(r); }

std::istream& operator>>(std::istream& s, vnl_decnum& r) {
  while (s.peek() == ' ' || s.peek() == '\t' || s.peek() == '\r') s.get();
  std::string text;
  const auto next_is = [&s](auto accept) {
    const int c = s.peek();
    return c != std::char_traits<char>::eof() && accept(static_cast<char>(c));
  };
  const auto is_sign = [](char c) { return c == '+' || c == '-'; };
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  const auto is_letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  const auto take = [&s, &text]() { text.push_back(static_cast<char>(s.get())); };
  if (next_is(is_sign)) take();
  if (next_is([](char c) { return c == 'I' || c == 'N'; })) {  // Inf, Infinity, NaN
    while (next_is(is_letter)) take();
  } else {
    while (next_is([&](char c) { return is_digit(c) || c == '.'; })) take();
    if (next_is([](char c) { return c == 'e'; })) {
      take();
      if (next_is(is_sign)) take();
      while (next_is(is_digit)) take();
    }
  }
  if (text.empty() && s.peek() == '\n') s.get();  // an empty line reads as zero, as upstream
  r = vnl_decnum(text);
  return s;
}

}  // inline namespace edgetrack_ports
