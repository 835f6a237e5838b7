// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_real_npolynomial.h: a real polynomial in several variables,
/// sum_i c_i prod_j x_j^p(i, j): coefficient i with exponent row i of the nterms x nvar matrix
/// p. Evaluation, partial derivatives, ring operations with other polynomials and scalars,
/// degrees, and merging of like terms (simplify).
#pragma once

#ifdef vnl_real_npolynomial_h_
#error "edgetrack's drop-in vnl/vnl_real_npolynomial.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>
#include <string>
#include <vector>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_real_npolynomial {
 public:
  vnl_real_npolynomial() = default;
  /// Coefficients c (one per term) and exponents p (one row per term, one column per variable).
  vnl_real_npolynomial(vnl_vector<double> c, const vnl_matrix<unsigned int>& p);

  double eval(const vnl_vector<double>& x) const;
  /// From precomputed powers: xn(j, k) = x_j^k for k up to the highest exponent of x_j.
  double eval(const vnl_matrix<double>& xn) const;
  /// d/dx_i at x, and the gradient at x.
  double deval(const vnl_vector<double>& x, unsigned int i) const;
  vnl_vector<double> deval(const vnl_vector<double>& x) const;
  /// The partial derivative with respect to variable i.
  vnl_real_npolynomial deriv(unsigned int i) const;

  vnl_real_npolynomial operator-() const;
  vnl_real_npolynomial operator+(const vnl_real_npolynomial& rhs) const;
  vnl_real_npolynomial operator-(const vnl_real_npolynomial& rhs) const { return *this + (-rhs); }
  vnl_real_npolynomial operator*(const vnl_real_npolynomial& rhs) const;
  vnl_real_npolynomial& operator+=(const vnl_real_npolynomial& rhs) { return *this = *this + rhs; }
  vnl_real_npolynomial& operator-=(const vnl_real_npolynomial& rhs) { return *this = *this - rhs; }
  vnl_real_npolynomial& operator*=(const vnl_real_npolynomial& rhs) { return *this = *this * rhs; }
  vnl_real_npolynomial operator+(double c) const;
  vnl_real_npolynomial operator-(double c) const { return *this + (-c); }
  vnl_real_npolynomial operator*(double c) const;
  vnl_real_npolynomial& operator*=(double c) { return *this = *this * c; }
  vnl_real_npolynomial operator/(double c) const { return *this * (1.0 / c); }
  vnl_real_npolynomial& operator/=(double c) { return *this *= 1.0 / c; }

  /// The highest total degree of a term.
  unsigned int degree() const;
  /// The highest exponent of any variable.
  unsigned int maxdegree() const;
  /// The highest exponent of each variable.
  std::vector<unsigned int> degrees() const;
  double& operator[](unsigned int i) { return coeffs_[i]; }
  double operator[](unsigned int i) const { return coeffs_[i]; }
  const vnl_vector<double>& coefficients() const { return coeffs_; }
  vnl_vector<double>& coefficients() { return coeffs_; }
  void set(const vnl_vector<double>& c, const vnl_matrix<unsigned int>& p);
  const vnl_matrix<unsigned int>& polyn() const { return polyn_; }
  vnl_matrix<unsigned int>& polyn() { return polyn_; }
  unsigned int nterms() const { return static_cast<unsigned>(coeffs_.size()); }
  unsigned int nvar() const { return static_cast<unsigned>(polyn_.cols()); }
  /// e.g. "3 X^2 Y - Z + 1" (X, Y, Z for up to three variables, X1, X2... beyond).
  std::string asString() const;
  /// Merges terms with the same exponents and drops zero terms.
  void simplify();

 private:
  vnl_vector<double> coeffs_;
  vnl_matrix<unsigned int> polyn_;
};

inline vnl_real_npolynomial operator+(double c, const vnl_real_npolynomial& p) { return p + c; }
inline vnl_real_npolynomial operator-(double c, const vnl_real_npolynomial& p) { return -p + c; }
inline vnl_real_npolynomial operator*(double c, const vnl_real_npolynomial& p) { return p * c; }
std::ostream& operator<<(std::ostream& os, const vnl_real_npolynomial& p);

}  // inline namespace edgetrack_ports
