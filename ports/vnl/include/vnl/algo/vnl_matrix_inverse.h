// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_matrix_inverse.h: the (pseudo-)inverse of a matrix through
/// its SVD; converts to vnl_matrix<T>, so `vnl_matrix<double> Ainv = vnl_matrix_inverse<double>(A);`.
#pragma once

#ifdef vnl_matrix_inverse_h_
#error "edgetrack's drop-in vnl/algo/vnl_matrix_inverse.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/algo/vnl_svd.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
struct vnl_matrix_inverse : public vnl_svd<T> {
  explicit vnl_matrix_inverse(const vnl_matrix<T>& M) : vnl_svd<T>(M, 0.0) {}
  ~vnl_matrix_inverse() = default;

  operator vnl_matrix<T>() const { return this->inverse(); }
  vnl_matrix<T> as_matrix() const { return this->inverse(); }
};

template <class T>
vnl_vector<T> operator*(const vnl_matrix_inverse<T>& i, const vnl_vector<T>& b) {
  return i.solve(b);
}
template <class T>
vnl_matrix<T> operator*(const vnl_matrix_inverse<T>& i, const vnl_matrix<T>& B) {
  return i.solve(B);
}

}  // inline namespace edgetrack_ports
