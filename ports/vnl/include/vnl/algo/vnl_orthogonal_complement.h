// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_orthogonal_complement.h: an n x (n-1) matrix whose
/// orthonormal columns span the space orthogonal to v (from the SVD of v as a row).
#pragma once

#ifdef vnl_orthogonal_complement_h_
#error "edgetrack's drop-in vnl/algo/vnl_orthogonal_complement.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/algo/vnl_svd.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
vnl_matrix<T> vnl_orthogonal_complement(const vnl_vector<T>& v) {
  const std::size_t n = v.size();
  vnl_matrix<T> row(1, n);
  row.set_row(0, v);
  return vnl_svd<T>(row).V().extract(n, n - 1, 0, 1);
}

}  // inline namespace edgetrack_ports
