// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_fortran_copy.h: a column-major copy of a vnl_matrix, for code
/// that calls Fortran-ordered routines; converts to T*.
#pragma once

#ifdef vnl_fortran_copy_h_
#error "edgetrack's drop-in vnl/vnl_fortran_copy.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_fortran_copy {
 public:
  explicit vnl_fortran_copy(const vnl_matrix<T>& M)
      : sz(static_cast<int>(M.rows() * M.cols())), data(new T[M.rows() * M.cols()]) {
    for (std::size_t c = 0, k = 0; c < M.cols(); ++c) {
      for (std::size_t r = 0; r < M.rows(); ++r) data[k++] = M(r, c);
    }
  }
  vnl_fortran_copy(const vnl_fortran_copy&) = delete;
  vnl_fortran_copy& operator=(const vnl_fortran_copy&) = delete;
  ~vnl_fortran_copy() { delete[] data; }

  operator T*() { return data; }

 protected:
  int sz;
  T* data;
};

}  // inline namespace edgetrack_ports
