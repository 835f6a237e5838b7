// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_adjugate.h: the adjugate (transposed cofactor matrix) of a
/// square matrix, adj(A) A = det(A) I; each cofactor is a vnl_determinant of a minor.
#pragma once

#ifdef vnl_adjugate_h_
#error "edgetrack's drop-in vnl/algo/vnl_adjugate.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vnl/algo/vnl_determinant.h"
#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

template <class T>
void vnl_adjugate(const vnl_matrix<T>& A, vnl_matrix<T>* out) {
  const std::size_t n = A.rows();
  assert(A.cols() == n);
  out->set_size(n, n);
  if (n == 1) {
    (*out)(0, 0) = T(1);
    return;
  }
  vnl_matrix<T> minor(n - 1, n - 1);
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t c = 0; c < n; ++c) {
      for (std::size_t i = 0, mi = 0; i < n; ++i) {
        if (i == r) continue;
        for (std::size_t j = 0, mj = 0; j < n; ++j) {
          if (j != c) minor(mi, mj++) = A(i, j);
        }
        ++mi;
      }
      const T cofactor = vnl_determinant(minor);
      (*out)(c, r) = (r + c) % 2 == 0 ? cofactor : -cofactor;
    }
  }
}

template <class T>
vnl_matrix<T> vnl_adjugate(const vnl_matrix<T>& A) {
  vnl_matrix<T> result;
  vnl_adjugate(A, &result);
  return result;
}

}  // inline namespace edgetrack_ports
