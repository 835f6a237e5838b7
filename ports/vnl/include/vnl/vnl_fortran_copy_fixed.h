// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_fortran_copy_fixed.h: a column-major copy of a vnl_matrix_fixed,
/// held by value; converts to T*.
#pragma once

#ifdef vnl_fortran_copy_fixed_h_
#error "edgetrack's drop-in vnl/vnl_fortran_copy_fixed.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

template <class T, unsigned R, unsigned C>
class vnl_fortran_copy_fixed {
 public:
  explicit vnl_fortran_copy_fixed(const vnl_matrix_fixed<T, R, C>& M) {
    for (unsigned c = 0, k = 0; c < C; ++c) {
      for (unsigned r = 0; r < R; ++r) data[k++] = M(r, c);
    }
  }
  operator T*() { return data; }

 protected:
  T data[R * C];
};

}  // inline namespace edgetrack_ports
