// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_trace.h: the sum of the main diagonal.
#pragma once

#ifdef vnl_trace_h_
#error "edgetrack's drop-in vnl/vnl_trace.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

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

}  // inline namespace edgetrack_ports
