// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_generalized_eigensystem.h"

#include <iostream>

#include "vnl/algo/vnl_cholesky.h"
#include "vnl/algo/vnl_symmetric_eigensystem.h"

inline namespace edgetrack_ports {

namespace {

/// Solves L X = R for lower-triangular L, in place on R.
void solve_lower(const vnl_matrix<double>& L, vnl_matrix<double>& R) {
  for (unsigned c = 0; c < R.cols(); ++c)
    for (unsigned i = 0; i < L.rows(); ++i) {
      double v = R(i, c);
      for (unsigned k = 0; k < i; ++k) v -= L(i, k) * R(k, c);
      R(i, c) = v / L(i, i);
    }
}

/// Solves L^T X = R for lower-triangular L, in place on R.
void solve_lower_transposed(const vnl_matrix<double>& L, vnl_matrix<double>& R) {
  const unsigned n = L.rows();
  for (unsigned c = 0; c < R.cols(); ++c)
    for (unsigned i = n; i-- > 0;) {
      double v = R(i, c);
      for (unsigned k = i + 1; k < n; ++k) v -= L(k, i) * R(k, c);
      R(i, c) = v / L(i, i);
    }
}

}  // namespace

vnl_generalized_eigensystem::vnl_generalized_eigensystem(const vnl_matrix<double>& A, const vnl_matrix<double>& B)
    : n(A.rows()), V(A.rows(), A.cols()), D(A.rows()) {
  const vnl_cholesky_of<double> chol(B, vnl_cholesky_of<double>::quiet);
  if (chol.rank_deficiency() != 0) {
    std::cerr << "vnl_generalized_eigensystem: B is not positive definite (leading minor " << chol.rank_deficiency()
              << ")\n";
  }
  const vnl_matrix<double> L = chol.lower_triangle();
  // M = L^-1 A L^-T: solve L Y = A, then L Z = Y^T (Y^T = A L^-T since A is symmetric).
  vnl_matrix<double> Y = A;
  solve_lower(L, Y);
  vnl_matrix<double> M = Y.transpose();
  solve_lower(L, M);
  M = (M + M.transpose()) * 0.5;  // symmetric up to rounding
  vnl_matrix<double> eigenvectors;
  vnl_vector<double> eigenvalues;
  vnl_symmetric_eigensystem_compute(M, eigenvectors, eigenvalues);
  solve_lower_transposed(L, eigenvectors);
  V = eigenvectors;
  D = vnl_diag_matrix<double>(eigenvalues);
}

}  // inline namespace edgetrack_ports
