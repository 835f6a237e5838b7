// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_svd_fixed.h: vnl_svd for an R x C vnl_matrix_fixed, with
/// fixed-size results: U (R x C), W (C values, descending), V (C x C). Computed by our vnl_svd.
#pragma once

#ifdef vnl_svd_fixed_h_
#error "edgetrack's drop-in vnl/algo/vnl_svd_fixed.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/algo/vnl_svd.h"
#include "vnl/vnl_diag_matrix_fixed.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T, unsigned R, unsigned C>
class vnl_svd_fixed {
 public:
  using singval_t = typename vnl_numeric_traits<T>::abs_t;

  explicit vnl_svd_fixed(const vnl_matrix_fixed<T, R, C>& M, double zero_out_tol = 0.0)
      : svd_(M.as_matrix(), zero_out_tol) {
    copy_out();
  }
  void zero_out_absolute(double tol = 1e-8) {
    svd_.zero_out_absolute(tol);
    copy_out();
  }
  void zero_out_relative(double tol = 1e-8) {
    svd_.zero_out_relative(tol);
    copy_out();
  }
  int singularities() const { return svd_.singularities(); }
  unsigned int rank() const { return svd_.rank(); }
  singval_t well_condition() const { return svd_.well_condition(); }
  singval_t determinant_magnitude() const { return svd_.determinant_magnitude(); }
  singval_t norm() const { return svd_.norm(); }
  const vnl_matrix_fixed<T, R, C>& U() const { return U_; }
  T U(int i, int j) const { return U_(i, j); }
  const vnl_diag_matrix_fixed<singval_t, C>& W() const { return W_; }
  const vnl_diag_matrix_fixed<singval_t, C>& Winverse() const { return Winverse_; }
  singval_t W(int i) const { return W_[i]; }
  singval_t sigma_max() const { return W_[0]; }
  singval_t sigma_min() const { return W_[C - 1]; }
  const vnl_matrix_fixed<T, C, C>& V() const { return V_; }
  T V(int i, int j) const { return V_(i, j); }
  vnl_matrix_fixed<T, C, R> inverse() const { return pinverse(); }
  vnl_matrix_fixed<T, C, R> pinverse(unsigned int rank = ~0u) const {
    return vnl_matrix_fixed<T, C, R>(svd_.pinverse(rank));
  }
  vnl_matrix_fixed<T, R, C> tinverse(unsigned int rank = ~0u) const {
    return vnl_matrix_fixed<T, R, C>(svd_.tinverse(rank));
  }
  vnl_matrix_fixed<T, R, C> recompose(unsigned int rank = ~0u) const {
    return vnl_matrix_fixed<T, R, C>(svd_.recompose(rank));
  }
  vnl_vector_fixed<T, C> solve(const vnl_vector_fixed<T, R>& y) const {
    return vnl_vector_fixed<T, C>(svd_.solve(y.as_vector()));
  }
  vnl_vector_fixed<T, C> nullvector() const { return V_.get_column(C - 1); }
  vnl_vector_fixed<T, R> left_nullvector() const { return U_.get_column(C - 1); }
  bool valid() const { return svd_.valid(); }

 private:
  void copy_out() {
    U_ = vnl_matrix_fixed<T, R, C>(svd_.U());
    V_ = vnl_matrix_fixed<T, C, C>(svd_.V());
    for (unsigned i = 0; i < C; ++i) W_[i] = svd_.W(i), Winverse_[i] = svd_.Winverse()[i];
  }

  vnl_svd<T> svd_;
  vnl_matrix_fixed<T, R, C> U_;
  vnl_diag_matrix_fixed<singval_t, C> W_;
  vnl_diag_matrix_fixed<singval_t, C> Winverse_;
  vnl_matrix_fixed<T, C, C> V_;
};

}  // inline namespace edgetrack_ports
