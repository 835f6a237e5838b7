// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_operators.h: a strict weak order on vectors and matrices (size
/// first, then the elements lexicographically), so they can be keys of std::map and std::set.
#pragma once

#ifdef vnl_operators_h_
#error "edgetrack's drop-in vnl/vnl_operators.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

namespace vnl_operators_detail {
template <class It>
bool less(std::size_t na, It a, std::size_t nb, It b) {
  if (na != nb) return na < nb;
  for (std::size_t i = 0; i < na; ++i) {
    if (a[i] < b[i]) return true;
    if (b[i] < a[i]) return false;
  }
  return false;
}
}  // namespace vnl_operators_detail

template <class T>
bool operator<(const vnl_vector<T>& lhs, const vnl_vector<T>& rhs) {
  return vnl_operators_detail::less(lhs.size(), lhs.data_block(), rhs.size(), rhs.data_block());
}
template <class T>
bool operator<(const vnl_matrix<T>& lhs, const vnl_matrix<T>& rhs) {
  if (lhs.rows() != rhs.rows()) return lhs.rows() < rhs.rows();
  return vnl_operators_detail::less(lhs.size(), lhs.data_block(), rhs.size(), rhs.data_block());
}
template <class T, unsigned n>
bool operator<(const vnl_vector_fixed<T, n>& lhs, const vnl_vector_fixed<T, n>& rhs) {
  return vnl_operators_detail::less(n, lhs.data_block(), n, rhs.data_block());
}
template <class T, unsigned r, unsigned c>
bool operator<(const vnl_matrix_fixed<T, r, c>& lhs, const vnl_matrix_fixed<T, r, c>& rhs) {
  return vnl_operators_detail::less(r * c, lhs.data_block(), r * c, rhs.data_block());
}

}  // inline namespace edgetrack_ports
