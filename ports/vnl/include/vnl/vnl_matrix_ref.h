// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matrix_ref.h: a vnl_matrix viewing a row-major block it does not
/// own. Writes go to the block, assignment copies values into it, and it cannot change size.
#pragma once

#ifdef vnl_matrix_ref_h_
#error "edgetrack's drop-in vnl/vnl_matrix_ref.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_matrix_ref : public vnl_matrix<T> {
 public:
  /// Views the rows x cols row-major block at `data`; the block must outlive the view.
  vnl_matrix_ref(std::size_t rows, std::size_t cols, T* data) : vnl_matrix<T>(rows, cols, data, false) {}
  vnl_matrix_ref(const vnl_matrix_ref& other)
      : vnl_matrix<T>(other.rows(), other.cols(), const_cast<T*>(other.data_block()), false) {}
  ~vnl_matrix_ref() = default;

  /// Copies the values of `rhs` (same shape) into the viewed block.
  vnl_matrix_ref& operator=(const vnl_matrix<T>& rhs) {
    vnl_matrix<T>::operator=(rhs);
    return *this;
  }
  vnl_matrix_ref& operator=(const vnl_matrix_ref& rhs) {
    vnl_matrix<T>::operator=(rhs);
    return *this;
  }
  vnl_matrix<T>& non_const() { return *this; }
};

}  // inline namespace edgetrack_ports
