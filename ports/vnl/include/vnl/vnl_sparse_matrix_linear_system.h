// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_sparse_matrix_linear_system.h: the vnl_linear_system A x = b for a
/// vnl_sparse_matrix A (double or float; products are taken in double, as upstream), with the
/// Jacobi preconditioner 1 / diag(A^T A).
#pragma once

#ifdef vnl_sparse_matrix_linear_system_h_
#error "edgetrack's drop-in vnl/vnl_sparse_matrix_linear_system.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vnl/vnl_linear_system.h"
#include "vnl/vnl_sparse_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_sparse_matrix_linear_system : public vnl_linear_system {
 public:
  /// A and b must outlive the system.
  vnl_sparse_matrix_linear_system(const vnl_sparse_matrix<T>& A, const vnl_vector<T>& b)
      : vnl_linear_system(A.columns(), A.rows()), A_(A), b_(b) {
    assert(b.size() == A.rows());
  }
  void multiply(const vnl_vector<double>& x, vnl_vector<double>& y) const override {
    vnl_vector<T> xt(x.size()), yt;
    for (std::size_t i = 0; i < x.size(); ++i) xt[i] = T(x[i]);
    A_.mult(xt, yt);
    y.set_size(yt.size());
    for (std::size_t i = 0; i < yt.size(); ++i) y[i] = static_cast<double>(yt[i]);
  }
  void transpose_multiply(const vnl_vector<double>& y, vnl_vector<double>& x) const override {
    vnl_vector<T> yt(y.size()), xt;
    for (std::size_t i = 0; i < y.size(); ++i) yt[i] = T(y[i]);
    A_.pre_mult(yt, xt);
    x.set_size(xt.size());
    for (std::size_t i = 0; i < xt.size(); ++i) x[i] = static_cast<double>(xt[i]);
  }
  void get_rhs(vnl_vector<double>& b) const override {
    b.set_size(b_.size());
    for (std::size_t i = 0; i < b_.size(); ++i) b[i] = static_cast<double>(b_[i]);
  }
  void apply_preconditioner(const vnl_vector<double>& x, vnl_vector<double>& px) const override {
    vnl_vector<T> d;
    A_.diag_AtA(d);
    px.set_size(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double di = static_cast<double>(d[i]);
      px[i] = di == 0 ? x[i] : x[i] / di;
    }
  }

 private:
  const vnl_sparse_matrix<T>& A_;
  const vnl_vector<T>& b_;
};

}  // inline namespace edgetrack_ports
