// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_ldl_cholesky.h: M = L D L^T for a symmetric positive-definite
/// M, with L unit lower triangular and D diagonal, and its rank-one (M + v v^T) and rank-k
/// (M + W W^T) updates without refactoring. Ours: the square-root-free factorisation and
/// Gill, Golub, Murray and Saunders' update (upstream: LINPACK dpofa, then rescaling).
/// rank_deficiency() is 0, or the 1-based index of the first pivot that is not positive;
/// with estimate_condition, rcond() is 1 / (|M|_1 |M^-1|_1), computed exactly.
#pragma once

#ifdef vnl_ldl_cholesky_h_
#error "edgetrack's drop-in vnl/algo/vnl_ldl_cholesky.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_ldl_cholesky {
 public:
  enum Operation { quiet, verbose, estimate_condition };

  explicit vnl_ldl_cholesky(const vnl_matrix<double>& M, Operation mode = verbose);
  vnl_ldl_cholesky(const vnl_ldl_cholesky&) = delete;
  vnl_ldl_cholesky& operator=(const vnl_ldl_cholesky&) = delete;

  /// x with M x = b.
  vnl_vector<double> solve(const vnl_vector<double>& b) const;
  void solve(const vnl_vector<double>& b, vnl_vector<double>* x) const;
  /// Replaces y by x with L x = y.
  void solve_lx(vnl_vector<double>& y);
  /// det M, the product of D.
  double determinant() const;
  /// Makes the factors those of M + v v^T.
  void rank1_update(const vnl_vector<double>& v);
  /// Makes the factors those of M + W W^T.
  void update(const vnl_matrix<double>& W);
  vnl_matrix<double> inverse() const;
  const vnl_matrix<double>& lower_triangle() const { return L_; }
  vnl_matrix<double> upper_triangle() const { return L_.transpose(); }
  const vnl_vector<double>& diagonal() const { return d_; }
  /// x^T M^-1 x and x^T M x, from the factors.
  double xt_m_inv_x(const vnl_vector<double>& x) const;
  double xt_m_x(const vnl_vector<double>& x) const;
  int rank_deficiency() const { return num_dims_rank_def_; }
  double rcond() const { return rcond_; }
  vnl_vector<double>& nullvector() { return nullvector_; }
  const vnl_vector<double>& nullvector() const { return nullvector_; }

 protected:
  vnl_matrix<double> L_;
  vnl_vector<double> d_;
  double rcond_ = 0;
  int num_dims_rank_def_ = 0;
  vnl_vector<double> nullvector_;

 private:
  void inplace_solve(double* x) const;
};

}  // inline namespace edgetrack_ports
