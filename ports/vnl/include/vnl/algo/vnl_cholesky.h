// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_cholesky.h: M = L L^T for a symmetric positive definite M;
/// solve, determinant, inverse, the triangles, rank_deficiency and rcond. Upstream's class is
/// double only and calls LINPACK's dpofa/dpoco; ours is our own column Cholesky written on T
/// (vnl_cholesky_of<T>), and vnl_cholesky is its double instance, so upstream code compiles
/// unchanged. As dpofa, rank_deficiency() is the order of the first leading minor that is not
/// positive definite (0 when M is). rcond() with estimate_condition is 1 / (|M|_1 |M^-1|_1)
/// computed exactly from the factor, where dpoco estimates it; both are the same quantity.
#pragma once

#ifdef vnl_cholesky_h_
#error "edgetrack's drop-in vnl/algo/vnl_cholesky.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_cholesky_of {
 public:
  enum Operation { quiet, verbose, estimate_condition };

  explicit vnl_cholesky_of(const vnl_matrix<T>& M, Operation mode = verbose);

  /// x with M x = b.
  vnl_vector<T> solve(const vnl_vector<T>& b) const;
  void solve(const vnl_vector<T>& b, vnl_vector<T>* x) const;
  T determinant() const;
  vnl_matrix<T> inverse() const;
  /// L (lower) and L^T (upper), zeros elsewhere.
  vnl_matrix<T> lower_triangle() const;
  vnl_matrix<T> upper_triangle() const;
  vnl_matrix<T> L_badly_named_method() const { return lower_triangle(); }
  int rank_deficiency() const { return num_dims_rank_def_; }
  /// Reciprocal condition number in the 1-norm (estimate_condition mode; 0 otherwise).
  T rcond() const { return rcond_; }
  /// The vector reaching the smallest |M x| / |x| found with estimate_condition.
  vnl_vector<T>& nullvector() { return nullvector_; }
  const vnl_vector<T>& nullvector() const { return nullvector_; }

 private:
  vnl_matrix<T> L_;  // the factor in the lower triangle
  int num_dims_rank_def_ = 0;
  T rcond_ = T(0);
  vnl_vector<T> nullvector_;
};

using vnl_cholesky = vnl_cholesky_of<double>;

}  // inline namespace edgetrack_ports
