// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matrix_exp.h: exp(X) of a square matrix by its Taylor series,
/// summed until the bound on the remaining terms, |X|^n / n! / (1 - |X| / n) in the infinity
/// norm, is below max_err (upstream's criterion). Works for vnl_matrix and vnl_matrix_fixed.
#pragma once

#ifdef vnl_matrix_exp_h_
#error "edgetrack's drop-in vnl/vnl_matrix_exp.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

inline namespace edgetrack_ports {

/// expX = exp(X) to within max_err; returns true.
template <class SquareMatrix>
bool vnl_matrix_exp(const SquareMatrix& X, SquareMatrix& expX, double max_err) {
  assert(X.rows() == X.cols() && max_err > 0);
  const double norm = static_cast<double>(X.operator_inf_norm());
  expX = X;
  expX.set_identity();
  SquareMatrix term(X);  // X^n / n!
  double term_bound = norm;
  for (unsigned n = 1;; ++n) {
    expX += term;
    if (norm < n && term_bound / (1 - norm / n) < max_err) break;
    term = term * X;
    term /= typename SquareMatrix::element_type(static_cast<int>(n + 1));
    term_bound *= norm / (n + 1);
  }
  return true;
}

/// exp(X) to within 1e-10.
template <class SquareMatrix>
SquareMatrix vnl_matrix_exp(const SquareMatrix& X) {
  SquareMatrix result(X);
  vnl_matrix_exp(X, result, 1e-10);
  return result;
}

}  // inline namespace edgetrack_ports
