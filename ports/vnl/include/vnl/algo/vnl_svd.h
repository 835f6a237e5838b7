// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_svd.h: the singular value decomposition M = U W V^T of an
/// m x n matrix, with upstream's interface: U (m x n), W (n singular values, descending), V
/// (n x n), rank after zeroing small values, (pseudo-)inverse, solve, null spaces.
///
/// Algorithm: upstream calls LINPACK's dsvdc (Householder bidiagonalisation and QR sweeps).
/// Ours is our own one-sided Jacobi (Hestenes) method: plane rotations of the columns of M
/// until every pair is orthogonal, then the column norms are the singular values. The results
/// agree with upstream's to rounding (the test checks U W V^T == M and U, V orthonormal to
/// 1e-12 relative in double) except that a singular vector may differ in sign, as any two SVD
/// codes may. It works in T throughout, so a fixed-point `real` SVD has no floating point.
#pragma once

#ifdef vnl_svd_h_
#error "edgetrack's drop-in vnl/algo/vnl_svd.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_numeric_traits.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_svd {
 public:
  using singval_t = typename vnl_numeric_traits<T>::abs_t;

  /// Decomposes M. zero_out_tol >= 0 zeroes singular values <= zero_out_tol; a negative value
  /// zeroes those <= -zero_out_tol * sigma_max (as upstream).
  explicit vnl_svd(const vnl_matrix<T>& M, double zero_out_tol = 0.0);

  /// Zeroes the singular values <= tol (and their inverses); updates rank().
  void zero_out_absolute(double tol = 1e-8);
  /// Zeroes the singular values <= tol * sigma_max.
  void zero_out_relative(double tol = 1e-8);
  int singularities() const { return static_cast<int>(W_.rows()) - static_cast<int>(rank()); }
  unsigned int rank() const { return rank_; }
  /// sigma_min / sigma_max.
  singval_t well_condition() const { return sigma_min() / sigma_max(); }
  /// |det M| for square M: the product of the singular values.
  singval_t determinant_magnitude() const;
  /// The two-norm of M, sigma_max.
  singval_t norm() const { return sigma_max(); }

  vnl_matrix<T>& U() { return U_; }
  const vnl_matrix<T>& U() const { return U_; }
  T U(int i, int j) const { return U_(i, j); }
  vnl_diag_matrix<singval_t>& W() { return W_; }
  const vnl_diag_matrix<singval_t>& W() const { return W_; }
  vnl_diag_matrix<singval_t>& Winverse() { return Winverse_; }
  const vnl_diag_matrix<singval_t>& Winverse() const { return Winverse_; }
  singval_t& W(int i, int j) { return W_(i, j); }
  singval_t& W(int i) { return W_(i, i); }
  singval_t W(int i, int j) const { return W_(i, j); }
  singval_t W(int i) const { return W_(i, i); }
  singval_t sigma_max() const { return W_[0]; }
  singval_t sigma_min() const { return W_[n_ - 1]; }
  vnl_matrix<T>& V() { return V_; }
  const vnl_matrix<T>& V() const { return V_; }
  T V(int i, int j) const { return V_(i, j); }

  /// The pseudo-inverse V W^+ U^T.
  vnl_matrix<T> inverse() const { return pinverse(); }
  /// The pseudo-inverse keeping only the largest `rank` singular values.
  vnl_matrix<T> pinverse(unsigned int rank = ~0u) const;
  /// The pseudo-inverse of M^T, U W^+ V^T.
  vnl_matrix<T> tinverse(unsigned int rank = ~0u) const;
  /// U W V^T with only the largest `rank` singular values.
  vnl_matrix<T> recompose(unsigned int rank = ~0u) const;
  /// The least-squares (minimum-norm) X with M X = B, and x with M x = y.
  vnl_matrix<T> solve(const vnl_matrix<T>& B) const;
  vnl_vector<T> solve(const vnl_vector<T>& y) const;
  void solve(const T* rhs, T* lhs) const;
  /// x = V W^+ U^T rhs, when the caller has already applied nothing (upstream's name).
  void solve_preinverted(const vnl_vector<T>& rhs, vnl_vector<T>* out) const;
  /// The right singular vectors of the zeroed singular values (columns), or the last
  /// `required_nullspace_dimension` of them.
  vnl_matrix<T> nullspace() const;
  vnl_matrix<T> nullspace(int required_nullspace_dimension) const;
  vnl_matrix<T> left_nullspace() const;
  vnl_matrix<T> left_nullspace(int required_nullspace_dimension) const;
  /// The right (left) singular vector of the smallest singular value.
  vnl_vector<T> nullvector() const;
  vnl_vector<T> left_nullvector() const;
  /// False if the rotations did not converge (never seen in practice; upstream: dsvdc's info).
  bool valid() const { return valid_; }

 private:
  void complete_u_basis();
  /// Zeroes the singular values <= limit and their inverses; sets rank_.
  void zero_out_below(const singval_t& limit);

  unsigned m_, n_;
  vnl_matrix<T> U_;
  vnl_diag_matrix<singval_t> W_;
  vnl_diag_matrix<singval_t> Winverse_;
  vnl_matrix<T> V_;
  unsigned rank_ = 0;
  bool valid_ = true;
  double last_tol_ = 0;
};

/// Prints U, W and V.
template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_svd<T>& svd);

}  // inline namespace edgetrack_ports
