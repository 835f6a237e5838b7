// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_matrix_update.h: the rank-one update M += a b^T in place.
#pragma once

#ifdef vnl_matrix_update_h_
#error "edgetrack's drop-in vnl/algo/vnl_matrix_update.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
void vnl_matrix_update(vnl_matrix<T>& M, const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == M.rows() && b.size() == M.cols());
  for (std::size_t i = 0; i < M.rows(); ++i) {
    for (std::size_t j = 0; j < M.cols(); ++j) M(i, j) += a[i] * b[j];
  }
}

}  // inline namespace edgetrack_ports
