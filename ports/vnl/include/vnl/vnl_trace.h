// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_trace.h: the sum of the main diagonal.
#pragma once

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"

template <class T>
T vnl_trace(const vnl_matrix<T>& m) {
  T total(0);
  for (std::size_t i = 0; i < m.rows() && i < m.cols(); ++i) total += m(i, i);
  return total;
}

template <class T, unsigned r, unsigned c>
T vnl_trace(const vnl_matrix_fixed<T, r, c>& m) {
  T total(0);
  for (unsigned i = 0; i < r && i < c; ++i) total += m(i, i);
  return total;
}
