// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_linear_operators_3.h: unrolled 3-D products and sums on
/// vnl_double_3 and vnl_double_3x3 (the generic vnl_matrix_fixed operators give the same
/// values; these are upstream's hand-unrolled overloads).
#pragma once

#ifdef vnl_linear_operators_3_h_
#error "edgetrack's drop-in vnl/vnl_linear_operators_3.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_double_3.h"
#include "vnl/vnl_double_3x3.h"

inline namespace edgetrack_ports {

inline vnl_double_3 operator*(const vnl_double_3x3& A, const vnl_double_3& x) {
  const double* a = A.data_block();
  return vnl_double_3(a[0] * x[0] + a[1] * x[1] + a[2] * x[2], a[3] * x[0] + a[4] * x[1] + a[5] * x[2],
                      a[6] * x[0] + a[7] * x[1] + a[8] * x[2]);
}
inline vnl_double_3 operator+(const vnl_double_3& a, const vnl_double_3& b) {
  return vnl_double_3(a[0] + b[0], a[1] + b[1], a[2] + b[2]);
}
inline vnl_double_3x3 operator*(const vnl_double_3x3& A, const vnl_double_3x3& B) {
  vnl_double_3x3 result;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) result(i, j) = A(i, 0) * B(0, j) + A(i, 1) * B(1, j) + A(i, 2) * B(2, j);
  }
  return result;
}

}  // inline namespace edgetrack_ports
