// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_real_polynomial.h: a polynomial with double coefficients, stored
/// as upstream stores them, highest power first: a[0] x^d + a[1] x^(d-1) + ... + a[d].
#pragma once

#ifdef vnl_real_polynomial_h_
#error "edgetrack's drop-in vnl/vnl_real_polynomial.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>
#include <iosfwd>

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_real_polynomial {
 public:
  /// Coefficients highest power first; an empty vector gives the zero polynomial.
  explicit vnl_real_polynomial(const vnl_vector<double>& a);
  vnl_real_polynomial(const double* a, unsigned len);
  /// The constant a; implicit as upstream, so that `p - 2.0` and `2.0 * p` read as polynomials.
  vnl_real_polynomial(double a) : coeffs_(1, a) {}
  /// The zero polynomial of degree d (d + 1 zero coefficients).
  vnl_real_polynomial(int d);
  vnl_real_polynomial(unsigned d) : coeffs_(std::size_t(d) + 1, 0.0) {}

  bool operator==(const vnl_real_polynomial& p) const { return p.coefficients() == coeffs_; }

  /// p(x) by Horner's rule.
  double evaluate(double x) const;
  std::complex<double> evaluate(const std::complex<double>& x) const;
  /// p'(x).
  double devaluate(double x) const;
  std::complex<double> devaluate(const std::complex<double>& x) const;
  /// The primitive with zero constant, at x; and the integral from x1 to x2.
  double evaluate_integral(double x) const;
  double evaluate_integral(double x1, double x2) const;

  vnl_real_polynomial derivative() const;
  /// The primitive whose constant term is zero.
  vnl_real_polynomial primitive() const;

  vnl_real_polynomial& operator+=(const vnl_real_polynomial& rhs);
  vnl_real_polynomial& operator-=(const vnl_real_polynomial& rhs);
  vnl_real_polynomial& operator*=(const vnl_real_polynomial& rhs);
  vnl_real_polynomial& operator*=(double s) {
    coeffs_ *= s;
    return *this;
  }

  int degree() const { return static_cast<int>(coeffs_.size()) - 1; }
  /// Coefficient i, highest power first.
  double& operator[](int i) { return coeffs_[static_cast<std::size_t>(i)]; }
  double operator[](int i) const { return coeffs_[static_cast<std::size_t>(i)]; }
  const vnl_vector<double>& coefficients() const { return coeffs_; }
  vnl_vector<double>& coefficients() { return coeffs_; }
  void set_coefficients(const vnl_vector<double>& coeffs) { coeffs_ = coeffs; }
  /// Prints as upstream does, e.g. " 2 X^2 -X +3".
  void print(std::ostream& os) const;

 private:
  vnl_vector<double> coeffs_;
};

vnl_real_polynomial operator+(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2);
vnl_real_polynomial operator-(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2);
vnl_real_polynomial operator*(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2);
vnl_real_polynomial operator*(double s, const vnl_real_polynomial& f);
vnl_real_polynomial operator*(const vnl_real_polynomial& f, double s);
/// sqrt of the mean of (f2 - f1)^2 over [x1, x2] (0 when x1 == x2).
double vnl_rms_difference(const vnl_real_polynomial& f1, const vnl_real_polynomial& f2, double x1, double x2);
std::ostream& operator<<(std::ostream& os, const vnl_real_polynomial& p);

}  // inline namespace edgetrack_ports
