// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_polynomial.h: a polynomial over T, stored as upstream stores it,
/// lowest power first (coefficients()[i] multiplies X^i), the highest coefficient nonzero; the
/// zero polynomial has no coefficients and degree -1. Ring operations, division with
/// remainder, derivative, primitive and evaluation.
#pragma once

#ifdef vnl_polynomial_h_
#error "edgetrack's drop-in vnl/vnl_polynomial.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <iosfwd>
#include <vector>

#include "vnl/vnl_numeric_traits.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_polynomial {
 public:
  /// Coefficients lowest power first; the last must be nonzero.
  vnl_polynomial(std::vector<T> a) : coeffs_(std::move(a)) { trim(); }
  /// Coefficients highest power first, as vnl_real_polynomial takes them.
  vnl_polynomial(const T* a, unsigned len) {
    while (len--) coeffs_.push_back(a[len]);
    trim();
  }
  /// The constant a (the zero polynomial for a == 0).
  vnl_polynomial(const T& a) : coeffs_(1u, a) { trim(); }
  /// d + 1 zero coefficients (upstream's storage for a polynomial to be filled in).
  vnl_polynomial(int d = -1) : coeffs_(static_cast<std::size_t>(d + 1), T(0)) { assert(d >= -1); }

  bool operator==(const vnl_polynomial& p) const { return p.coefficients() == coeffs_; }
  bool operator!=(const vnl_polynomial& p) const { return !(*this == p); }
  vnl_polynomial operator-() const;
  vnl_polynomial operator+(const vnl_polynomial& f) const;
  vnl_polynomial operator-(const vnl_polynomial& f) const { return operator+(-f); }
  vnl_polynomial operator*(const vnl_polynomial& f) const;
  /// The quotient and the remainder of polynomial long division.
  vnl_polynomial operator/(const vnl_polynomial& f) const;
  vnl_polynomial operator%(const vnl_polynomial& f) const;
  vnl_polynomial& operator+=(const vnl_polynomial& f) { return *this = operator+(f); }
  vnl_polynomial& operator-=(const vnl_polynomial& f) { return *this = operator-(f); }
  vnl_polynomial& operator*=(const vnl_polynomial& f) { return *this = operator*(f); }
  vnl_polynomial& operator/=(const vnl_polynomial& f) { return *this = operator/(f); }
  vnl_polynomial& operator%=(const vnl_polynomial& f) { return *this = operator%(f); }

  /// p(x) by Horner's rule.
  T evaluate(const T& x) const;
  vnl_polynomial derivative() const;
  T devaluate(const T& x) const { return derivative().evaluate(x); }
  /// The primitive with zero constant term.
  vnl_polynomial primitive() const;
  T evaluate_integral(const T& x) const { return primitive().evaluate(x); }
  T evaluate_integral(const T& x1, const T& x2) const { return evaluate_integral(x2) - evaluate_integral(x1); }

  int degree() const { return static_cast<int>(coeffs_.size()) - 1; }
  T& operator[](unsigned i) { return coeffs_[i]; }
  T operator[](unsigned i) const { return coeffs_[i]; }
  const std::vector<T>& coefficients() const { return coeffs_; }
  std::vector<T>& coefficients() { return coeffs_; }
  void set_coefficients(const std::vector<T>& coeffs) { coeffs_ = coeffs; }
  /// Prints as upstream does, highest power first: " X^3 +2 X^2 +3 X +4".
  void print(std::ostream& os) const;

 protected:
  void trim() {
    while (!coeffs_.empty() && coeffs_.back() == T(0)) coeffs_.pop_back();
  }
  std::vector<T> coeffs_;
};

template <class T>
std::ostream& operator<<(std::ostream& os, const vnl_polynomial<T>& p);

}  // inline namespace edgetrack_ports
