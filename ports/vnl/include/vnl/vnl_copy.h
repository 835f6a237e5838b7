// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_copy.h: element-wise copies between containers of different
/// scalars (vnl_vector<float> to vnl_vector<double> and so on). Each element is converted with
/// an explicit T(value), so fixed point converts too.
#pragma once

#ifdef vnl_copy_h_
#error "edgetrack's drop-in vnl/vnl_copy.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <cstddef>

#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

/// Copies n elements from src to dst, converting each.
template <class S, class T>
void vnl_copy(const S* src, T* dst, unsigned n) {
  for (unsigned i = 0; i < n; ++i) dst[i] = T(src[i]);
}

template <class S, class T>
void vnl_copy(const vnl_vector<S>& src, vnl_vector<T>& dst) {
  assert(src.size() == dst.size());
  vnl_copy(src.data_block(), dst.data_block(), static_cast<unsigned>(src.size()));
}

template <class S, class T>
void vnl_copy(const vnl_matrix<S>& src, vnl_matrix<T>& dst) {
  assert(src.rows() == dst.rows() && src.cols() == dst.cols());
  vnl_copy(src.data_block(), dst.data_block(), static_cast<unsigned>(src.size()));
}

template <class S, class T, unsigned n>
void vnl_copy(const vnl_vector_fixed<S, n>& src, vnl_vector_fixed<T, n>& dst) {
  vnl_copy(src.data_block(), dst.data_block(), n);
}

template <class S, class T, unsigned r, unsigned c>
void vnl_copy(const vnl_matrix_fixed<S, r, c>& src, vnl_matrix_fixed<T, r, c>& dst) {
  vnl_copy(src.data_block(), dst.data_block(), r * c);
}

template <class S, class T>
void vnl_copy(const vnl_diag_matrix<S>& src, vnl_diag_matrix<T>& dst) {
  assert(src.size() == dst.size());
  for (unsigned i = 0; i < src.size(); ++i) dst[i] = T(src[i]);
}

}  // inline namespace edgetrack_ports
