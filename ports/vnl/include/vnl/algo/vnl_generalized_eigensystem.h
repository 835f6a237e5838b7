// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_generalized_eigensystem.h: A x = lambda B x for symmetric A
/// and positive-definite B (Golub and van Loan 8.7): with B = L L^T (vnl_cholesky) it solves the
/// symmetric L^-1 A L^-T y = lambda y (vnl_symmetric_eigensystem) and takes x = L^-T y, so the
/// eigenvectors are B-orthonormal. Eigenvalues in increasing order; a warning on stderr when B
/// is not positive definite.
#pragma once

#ifdef vnl_generalized_eigensystem_h_
#error "edgetrack's drop-in vnl/algo/vnl_generalized_eigensystem.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

class vnl_generalized_eigensystem {
 public:
  long n;
  vnl_generalized_eigensystem(const vnl_matrix<double>& A, const vnl_matrix<double>& B);
  /// The eigenvectors, as columns.
  vnl_matrix<double> V;
  /// The eigenvalues.
  vnl_diag_matrix<double> D;
};

}  // inline namespace edgetrack_ports
