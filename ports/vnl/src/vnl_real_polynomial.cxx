// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_real_polynomial.h"

#include <cassert>
#include <cmath>
#include <ostream>

inline namespace edgetrack_ports {

namespace {
template <class X>
X horner(const vnl_vector<double>& a, const X& x) {
  X total(0);
  for (std::size_t i = 0; i < a.size(); ++i) total = total * x + a[i];
  return total;
}

/// Coefficients highest first, padded with leading zeros to n.
vnl_vector<double> padded(const vnl_vector<double>& a, std::size_t n) {
  vnl_vector<double> result(n, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) result[n - a.size() + i] = a[i];
  return result;
}
}  // namespace

vnl_real_polynomial::vnl_real_polynomial(const vnl_vector<double>& a) : coeffs_(a) {
  if (coeffs_.empty()) coeffs_ = vnl_vector<double>(1, 0.0);
}

vnl_real_polynomial::vnl_real_polynomial(const double* a, unsigned len) : coeffs_(a, len) {
  if (coeffs_.empty()) coeffs_ = vnl_vector<double>(1, 0.0);
}

vnl_real_polynomial::vnl_real_polynomial(int d) : coeffs_(static_cast<std::size_t>(d + 1), 0.0) { assert(d >= 0); }

double vnl_real_polynomial::evaluate(double x) const { return horner(coeffs_, x); }

std::complex<double> vnl_real_polynomial::evaluate(const std::complex<double>& x) const { return horner(coeffs_, x); }

double vnl_real_polynomial::devaluate(double x) const { return derivative().evaluate(x); }

std::complex<double> vnl_real_polynomial::devaluate(const std::complex<double>& x) const {
  return derivative().evaluate(x);
}

double vnl_real_polynomial::evaluate_integral(double x) const { return primitive().evaluate(x); }

double vnl_real_polynomial::evaluate_integral(double x1, double x2) const {
  const vnl_real_polynomial p = primitive();
  return p.evaluate(x2) - p.evaluate(x1);
}

vnl_real_polynomial vnl_real_polynomial::derivative() const {
  const int d = degree();
  if (d == 0) return vnl_real_polynomial(0.0);
  vnl_vector<double> result(static_cast<std::size_t>(d));
  for (int i = 0; i < d; ++i) result[i] = coeffs_[i] * (d - i);
  return vnl_real_polynomial(result);
}

vnl_real_polynomial vnl_real_polynomial::primitive() const {
  const int d = degree();
  vnl_vector<double> result(static_cast<std::size_t>(d + 2), 0.0);
  for (int i = 0; i <= d; ++i) result[i] = coeffs_[i] / (d + 1 - i);
  return vnl_real_polynomial(result);
}

vnl_real_polynomial& vnl_real_polynomial::operator+=(const vnl_real_polynomial& rhs) { return *this = *this + rhs; }
vnl_real_polynomial& vnl_real_polynomial::operator-=(const vnl_real_polynomial& rhs) { return *this = *this - rhs; }
vnl_real_polynomial& vnl_real_polynomial::operator*=(const vnl_real_polynomial& rhs) { return *this = *this * rhs; }

vnl_real_polynomial operator+(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2) {
  const std::size_t n = std::max(f1.coefficients().size(), f2.coefficients().size());
  return vnl_real_polynomial(padded(f1.coefficients(), n) + padded(f2.coefficients(), n));
}

vnl_real_polynomial operator-(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2) {
  const std::size_t n = std::max(f1.coefficients().size(), f2.coefficients().size());
  return vnl_real_polynomial(padded(f1.coefficients(), n) - padded(f2.coefficients(), n));
}

vnl_real_polynomial operator*(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2) {
  const vnl_vector<double>& a = f1.coefficients();
  const vnl_vector<double>& b = f2.coefficients();
  vnl_vector<double> product(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) product[i + j] += a[i] * b[j];
  }
  return vnl_real_polynomial(product);
}

vnl_real_polynomial operator*(double s, const vnl_real_polynomial& f) { return vnl_real_polynomial(f.coefficients() * s); }
vnl_real_polynomial operator*(const vnl_real_polynomial& f, double s) { return s * f; }

double vnl_rms_difference(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2, double x1, double x2) {
  const double width = std::fabs(x2 - x1);
  if (width == 0.0) return 0.0;
  const vnl_real_polynomial difference = f2 - f1;
  const double area = std::fabs((difference * difference).evaluate_integral(x1, x2));
  return std::sqrt(area / width);
}

void vnl_real_polynomial::print(std::ostream& os) const {
  // Upstream's format: " X^3 +2 X^2 -X +4": each nonzero term after a space, '+' before a
  // positive term that is not the first, unit coefficients shown only as their sign.
  const int d = degree();
  bool first = true;
  for (int i = 0; i <= d; ++i) {
    const double a = coeffs_[i];
    if (a == 0.0) continue;
    const int power = d - i;
    os << ' ';
    if (a > 0.0 && !first) os << '+';
    if (power == 0) {
      os << a;
    } else if (a == -1.0) {
      os << '-';
    } else if (a != 1.0) {
      os << a << ' ';
    }
    if (power > 1) {
      os << "X^" << power;
    } else if (power == 1) {
      os << 'X';
    }
    first = false;
  }
  if (first) os << " 0";
}

std::ostream& operator<<(std::ostream& os, const vnl_real_polynomial& p) {
  p.print(os);
  return os;
}

}  // inline namespace edgetrack_ports
