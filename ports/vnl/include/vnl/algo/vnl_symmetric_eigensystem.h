// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_symmetric_eigensystem.h: A = V D V^T for a symmetric A, the
/// eigenvalues in D in ascending order and the unit eigenvectors as the columns of V. Upstream
/// calls EISPACK's rs (tridiagonalisation and QL); ours is our own cyclic Jacobi method on T,
/// which reaches the same eigenpairs to rounding (an eigenvector may differ in sign, and for a
/// repeated eigenvalue any orthonormal basis of its space is an answer, for both codes).
#pragma once

#ifdef vnl_symmetric_eigensystem_h_
#error "edgetrack's drop-in vnl/algo/vnl_symmetric_eigensystem.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

/// The eigenvalues l1 <= l2 <= l3 of the symmetric 3x3 matrix [M11 M12 M13; . M22 M23; . . M33]
/// (upstream computes them in closed form; we use the same Jacobi iteration).
template <class T>
void vnl_symmetric_eigensystem_compute_eigenvals(T M11, T M12, T M13, T M22, T M23, T M33, T& l1, T& l2, T& l3);

/// Fills V (eigenvectors as columns) and D (ascending eigenvalues); false if A is not square.
template <class T>
bool vnl_symmetric_eigensystem_compute(const vnl_matrix<T>& A, vnl_matrix<T>& V, vnl_vector<T>& D);

template <class T>
class vnl_symmetric_eigensystem {
 public:
  explicit vnl_symmetric_eigensystem(const vnl_matrix<T>& M);

  int n;
  vnl_matrix<T> V;
  vnl_diag_matrix<T> D;

  vnl_vector<T> get_eigenvector(int i) const { return V.get_column(static_cast<std::size_t>(i)); }
  T get_eigenvalue(int i) const { return D[static_cast<unsigned>(i)]; }
  /// The eigenvector of the smallest eigenvalue.
  vnl_vector<T> nullvector() const { return get_eigenvector(0); }
  vnl_matrix<T> recompose() const { return V * D * V.transpose(); }
  T determinant() const { return D.determinant(); }
  /// V D^+ V^T, inverting only the nonzero eigenvalues.
  vnl_matrix<T> pinverse() const;
  vnl_matrix<T> inverse() const { return pinverse(); }
  /// V sqrt(D) V^T (negative eigenvalues count as zero) and its inverse.
  vnl_matrix<T> square_root() const;
  vnl_matrix<T> inverse_square_root() const;
  /// x with M x = b.
  vnl_vector<T> solve(const vnl_vector<T>& b);
  void solve(const vnl_vector<T>& b, vnl_vector<T>* x) { *x = solve(b); }
};

}  // inline namespace edgetrack_ports
