// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_vector_ref.h: a vnl_vector viewing memory it does not own.
/// Writes go to that memory, assignment copies values into it, and it cannot change size.
#pragma once

#ifdef vnl_vector_ref_h_
#error "edgetrack's drop-in vnl/vnl_vector_ref.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_vector_ref : public vnl_vector<T> {
 public:
  /// Views n elements at `space`; the memory must outlive the view.
  vnl_vector_ref(std::size_t n, T* space) : vnl_vector<T>(n, space, false) {}
  /// Another view of the same memory.
  vnl_vector_ref(const vnl_vector_ref& v) : vnl_vector<T>(v.size(), const_cast<T*>(v.data_block()), false) {}
  ~vnl_vector_ref() = default;

  /// Copies the values of `rhs` (same size) into the viewed memory.
  vnl_vector_ref& operator=(const vnl_vector<T>& rhs) {
    vnl_vector<T>::operator=(rhs);
    return *this;
  }
  vnl_vector_ref& operator=(const vnl_vector_ref& rhs) {
    vnl_vector<T>::operator=(rhs);
    return *this;
  }
  /// The view as a modifiable vnl_vector (upstream's escape from a const view).
  vnl_vector<T>& non_const() { return *this; }
};

}  // inline namespace edgetrack_ports
