// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_transpose.h: vnl_transpose(M) stands for M^T in a product, so
/// vnl_transpose(A) * B and A * vnl_transpose(B) compute A^T B and A B^T without forming the
/// transpose first.
#pragma once

#ifdef vnl_transpose_h_
#error "edgetrack's drop-in vnl/vnl_transpose.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_transpose_base {};

template <class T>
class vnl_transpose_of : public vnl_transpose_base {
 public:
  explicit vnl_transpose_of(const vnl_matrix<T>& m) : m_(m) {}
  /// The transpose as a matrix.
  vnl_matrix<T> asMatrix() const { return m_.transpose(); }
  operator vnl_matrix<T>() const { return asMatrix(); }
  const vnl_matrix<T>& matrix() const { return m_; }

 private:
  const vnl_matrix<T>& m_;
};

/// The transpose of m as a product operand; m must outlive the expression.
template <class T>
vnl_transpose_of<T> vnl_transpose(const vnl_matrix<T>& m) {
  return vnl_transpose_of<T>(m);
}

/// A^T * B.
template <class T>
vnl_matrix<T> operator*(const vnl_transpose_of<T>& at, const vnl_matrix<T>& b) {
  const vnl_matrix<T>& a = at.matrix();
  assert(a.rows() == b.rows());
  vnl_matrix<T> result(a.cols(), b.cols());
  for (std::size_t i = 0; i < a.cols(); ++i) {
    for (std::size_t j = 0; j < b.cols(); ++j) {
      T total(0);
      for (std::size_t k = 0; k < a.rows(); ++k) total += a(k, i) * b(k, j);
      result(i, j) = total;
    }
  }
  return result;
}
/// A * B^T.
template <class T>
vnl_matrix<T> operator*(const vnl_matrix<T>& a, const vnl_transpose_of<T>& bt) {
  const vnl_matrix<T>& b = bt.matrix();
  assert(a.cols() == b.cols());
  vnl_matrix<T> result(a.rows(), b.rows());
  for (std::size_t i = 0; i < a.rows(); ++i) {
    for (std::size_t j = 0; j < b.rows(); ++j) {
      T total(0);
      for (std::size_t k = 0; k < a.cols(); ++k) total += a(i, k) * b(j, k);
      result(i, j) = total;
    }
  }
  return result;
}
/// A^T * v.
template <class T>
vnl_vector<T> operator*(const vnl_transpose_of<T>& at, const vnl_vector<T>& v) {
  return v * at.matrix();
}
/// A^T * B^T = (B A)^T.
template <class T>
vnl_matrix<T> operator*(const vnl_transpose_of<T>& at, const vnl_transpose_of<T>& bt) {
  return (bt.matrix() * at.matrix()).transpose();
}

}  // inline namespace edgetrack_ports
