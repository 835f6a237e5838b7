// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_cross_product_matrix.h: the 3x3 matrix [v]x with
/// [v]x * w == vnl_cross_3d(v, w).
#pragma once

#ifdef vnl_cross_product_matrix_h_
#error "edgetrack's drop-in vnl/vnl_cross_product_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_double_3x3.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

class vnl_cross_product_matrix : public vnl_double_3x3 {
 public:
  using base = vnl_double_3x3;

  vnl_cross_product_matrix(const vnl_vector_fixed<double, 3>& v) { set(v.data_block()); }
  vnl_cross_product_matrix(const vnl_vector<double>& v) { set(v.data_block()); }
  vnl_cross_product_matrix(const double* v) { set(v); }

  /// Sets this matrix to [v]x for v = (v[0], v[1], v[2]).
  vnl_cross_product_matrix& set(const double* v) {
    base& e = *this;
    e(0, 0) = 0, e(0, 1) = -v[2], e(0, 2) = v[1];
    e(1, 0) = v[2], e(1, 1) = 0, e(1, 2) = -v[0];
    e(2, 0) = -v[1], e(2, 1) = v[0], e(2, 2) = 0;
    return *this;
  }
};

}  // inline namespace edgetrack_ports
