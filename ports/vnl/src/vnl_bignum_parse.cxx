// SPDX-License-Identifier: BSD-3-Clause
// vnl_bignum's text input: upstream's literal forms, from a string or a stream.
#include <cctype>
#include <cstdint>
#include <cstring>
#include <istream>
#include <string>

#include "vnl/vnl_bignum.h"

inline namespace edgetrack_ports {

namespace {
/// a = a * factor + addend, on 16-bit digits (least significant first).
void multiply_add(std::vector<vnl_bignum::Data>& a, std::uint32_t factor, std::uint32_t addend) {
  std::uint32_t carry = addend;
  for (auto& digit : a) {
    carry += digit * factor;
    digit = static_cast<vnl_bignum::Data>(carry & 0xFFFFu);
    carry >>= 16;
  }
  if (carry) a.push_back(static_cast<vnl_bignum::Data>(carry));
}

int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

/// Reads digits below `base` from p into a; returns how many.
int read_digits(const char*& p, int base, std::vector<vnl_bignum::Data>& a) {
  int count = 0;
  for (; digit_value(*p) < base; ++p, ++count) multiply_add(a, static_cast<std::uint32_t>(base), digit_value(*p));
  return count;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// "Inf" and any prefix of "inity" after it, to the end of the text.
bool is_infinity_word(const char* p) {
  if (std::strncmp(p, "Inf", 3) != 0) return false;
  p += 3;
  for (const char* rest = "inity"; *rest && *p == *rest; ++rest) ++p;
  return *p == '\0';
}
}  // namespace

bool vnl_bignum::parse(const char* s) {
  *this = vnl_bignum();
  while (is_space(*s)) ++s;
  const char* p = s;
  const bool negative = *p == '-';
  if (*p == '+' || *p == '-') ++p;
  if (is_infinity_word(p)) {
    *this = infinity(negative ? -1 : 1);
    return true;
  }
  Digits magnitude;
  if (*p >= '1' && *p <= '9') {  // decimal, or exponential with a nonnegative exponent
    read_digits(p, 10, magnitude);
    if (*p == 'e' || *p == 'E') {
      ++p;
      if (*p == '+') ++p;
      Digits exponent;
      const char* exponent_text = p;
      if (read_digits(p, 10, exponent) == 0 || *p != '\0') return false;
      for (long e = std::atol(exponent_text); e > 0; --e) multiply_add(magnitude, 10, 0);
      *this = from_magnitude(magnitude, negative ? -1 : 1);
      return true;
    }
  } else if (*p == '0' && (p[1] == 'x' || p[1] == 'X')) {
    p += 2;
    if (read_digits(p, 16, magnitude) == 0) return false;
  } else if (*p == '0') {
    read_digits(p, 8, magnitude);
  } else {
    return false;
  }
  if (*p == 'l' || *p == 'L') ++p;
  if (*p != '\0') return false;
  *this = from_magnitude(magnitude, negative ? -1 : 1);
  return true;
}

vnl_bignum& vnl_bignum_from_string(vnl_bignum& b, const std::string& s) {
  const char* p = s.c_str();
  while (is_space(*p)) ++p;
  const bool negative = *p == '-';
  if (*p == '+' || *p == '-') ++p;
  if (is_infinity_word(p)) return b = vnl_bignum(s.c_str());
  vnl_bignum::Digits magnitude;
  read_digits(p, 10, magnitude);  // upstream reads the leading decimal digits only
  return b = vnl_bignum::from_magnitude(magnitude, negative ? -1 : 1);
}

std::istream& operator>>(std::istream& s, vnl_bignum& r) {
  r = vnl_bignum();
  std::string token;
  s >> std::ws;
  // The characters a literal can hold: a sign first or after an exponent mark, else alphanumerics.
  for (int c = s.peek(); c != std::char_traits<char>::eof(); c = s.peek()) {
    const bool sign_allowed = token.empty() || token.back() == 'e' || token.back() == 'E';
    if (!(std::isalnum(c) || (sign_allowed && (c == '+' || c == '-')))) break;
    token.push_back(static_cast<char>(s.get()));
  }
  if (token.empty() || !r.parse(token.c_str())) s.setstate(std::ios::failbit);
  return s;
}

}  // inline namespace edgetrack_ports
