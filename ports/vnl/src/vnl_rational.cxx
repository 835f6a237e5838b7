// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_rational.h"

#include <cassert>
#include <cmath>
#include <istream>
#include <limits>
#include <ostream>

inline namespace edgetrack_ports {

namespace {
using int_type = vnl_rational::int_type;
constexpr double kMaxInt = 9.2233720368547748e18;  // just below 2^63: products past it overflow

/// The continued fraction of d with upstream's stopping rule: a convergent is taken while the
/// remainder times the current numerator and denominator stays below 1e9, and the expansion
/// stops once the remainder drops under 1e-6 (so 0.42857142857 gives 3/7). Magnitudes from
/// 1e9 up, and infinities, give +-infinity, as upstream.
void continued_fraction(double d, int_type& num, int_type& den) {
  const bool negative = d < 0;
  double x = negative ? -d : d;
  int_type p0 = 0, q0 = 1, p1 = 1, q1 = 0;  // convergents p/q
  while (x * static_cast<double>(p1) < 1e9 && x * static_cast<double>(q1) < 1e9) {
    const auto whole = static_cast<int_type>(x);
    x -= static_cast<double>(whole);
    const int_type p2 = whole * p1 + p0, q2 = whole * q1 + q0;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    if (x < 1e-6) break;
    x = 1 / x;
  }
  num = negative ? -p1 : p1, den = q1;
}
}  // namespace

vnl_rational::vnl_rational(double d) {
  continued_fraction(d, num_, den_);
  normalize();
}

vnl_rational::int_type vnl_rational::gcd(int_type l1, int_type l2) {
  while (l2 != 0) {
    const int_type t = l1 % l2;
    l1 = l2, l2 = t;
  }
  return l1 < 0 ? -l1 : l1;
}

void vnl_rational::normalize() {
  assert(num_ != 0 || den_ != 0);  // 0/0 is undefined
  if (den_ == 0) {  // +-infinity
    num_ = num_ > 0 ? 1 : -1;
    return;
  }
  if (num_ == 0) {
    den_ = 1;
    return;
  }
  const int_type common = gcd(num_, den_);
  num_ /= common, den_ /= common;
  if (den_ < 0) num_ = -num_, den_ = -den_;
}

vnl_rational& vnl_rational::invert() {
  const int_type t = num_;
  num_ = den_, den_ = t;
  normalize();
  return *this;
}

vnl_rational& vnl_rational::operator+=(const vnl_rational& r) {
  if (den_ == r.den_) {
    num_ += r.num_;
    normalize();
    return *this;
  }
  const int_type c = gcd(den_, r.den_);
  const double n = static_cast<double>(num_) * static_cast<double>(r.den_ / c) +
                   static_cast<double>(den_ / c) * static_cast<double>(r.num_);
  const double d = static_cast<double>(den_) * static_cast<double>(r.den_ / c);
  if (std::fabs(n) >= kMaxInt || d >= kMaxInt) return *this = vnl_rational(n / d);
  num_ = num_ * (r.den_ / c) + (den_ / c) * r.num_;
  den_ *= r.den_ / c;
  normalize();
  return *this;
}

vnl_rational& vnl_rational::operator-=(const vnl_rational& r) { return *this += -r; }

vnl_rational& vnl_rational::operator*=(const vnl_rational& r) {
  assert((num_ != 0 || r.den_ != 0) && (r.num_ != 0 || den_ != 0));  // 0 * inf is undefined
  const int_type a = gcd(r.num_, den_), b = gcd(r.den_, num_);
  const int_type n1 = b ? num_ / b : num_, d1 = a ? den_ / a : den_;
  const int_type n2 = a ? r.num_ / a : r.num_, d2 = b ? r.den_ / b : r.den_;
  const double n = static_cast<double>(n1) * static_cast<double>(n2);
  const double d = static_cast<double>(d1) * static_cast<double>(d2);
  if (std::fabs(n) >= kMaxInt || d >= kMaxInt) return *this = vnl_rational(n / d);
  num_ = n1 * n2, den_ = d1 * d2;
  normalize();
  return *this;
}

vnl_rational& vnl_rational::operator/=(const vnl_rational& r) {
  assert(r.num_ != 0 || num_ != 0);  // 0 / 0 is undefined
  vnl_rational inverse(r);
  return *this *= inverse.invert();
}

vnl_rational& vnl_rational::operator%=(const vnl_rational& r) {
  assert(r.num_ != 0);
  const vnl_rational quotient = *this / r;
  return *this -= r * vnl_rational(quotient.truncate());
}

bool vnl_rational::operator<(const vnl_rational& rhs) const {
  if (den_ == rhs.den_) return num_ < rhs.num_;
  if (den_ == 0) return num_ < 0 && !(rhs.den_ == 0 && rhs.num_ < 0);
  if (rhs.den_ == 0) return rhs.num_ > 0;
  return static_cast<long double>(num_) * rhs.den_ < static_cast<long double>(rhs.num_) * den_;
}

vnl_rational::int_type vnl_rational::floor() const {
  const int_type t = truncate();
  return (num_ < 0 && den_ != 0 && t * den_ != num_) ? t - 1 : t;
}

vnl_rational::int_type vnl_rational::ceil() const {
  const int_type t = truncate();
  return (num_ > 0 && den_ != 0 && t * den_ != num_) ? t + 1 : t;
}

vnl_rational::int_type vnl_rational::round() const {
  if (den_ == 0) return num_;
  const int_type twice = (2 * num_ + (num_ < 0 ? -den_ : den_));  // 2 num +- den
  return twice / (2 * den_);
}

std::ostream& operator<<(std::ostream& s, const vnl_rational& r) {
  return s << r.numerator() << '/' << r.denominator();
}

std::istream& operator>>(std::istream& s, vnl_rational& r) {
  vnl_rational::int_type n = 0, d = 1;
  s >> n >> d;
  r.set(n, d);
  return s;
}

}  // inline namespace edgetrack_ports
