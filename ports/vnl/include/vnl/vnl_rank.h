// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_rank.h: the rank of a matrix by exact elimination (meant for
/// integer matrices, as upstream; a floating-point matrix is reduced with exact zero tests
/// too, so use vnl_svd for a numerical rank). Ours eliminates fraction-free (Bareiss), which
/// keeps integer matrices integer; the reduced matrices are in echelon form, not necessarily
/// upstream's exact entries, and have the same rank.
#pragma once

#ifdef vnl_rank_h_
#error "edgetrack's drop-in vnl/vnl_rank.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>
#include <utility>

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

enum vnl_rank_type { vnl_rank_row, vnl_rank_column, vnl_rank_both };
enum vnl_rank_pivot_type { vnl_rank_pivot_one, vnl_rank_pivot_all };

/// Row echelon form of mat by fraction-free elimination (the pivot choice is ignored: every
/// pivot is taken, as with vnl_rank_pivot_all).
template <class T>
vnl_matrix<T> vnl_rank_row_reduce(const vnl_matrix<T>& mat, vnl_rank_pivot_type = vnl_rank_pivot_all) {
  vnl_matrix<T> a(mat);
  const std::size_t m = a.rows(), n = a.cols();
  T previous(1);
  std::size_t row = 0;
  for (std::size_t c = 0; c < n && row < m; ++c) {
    std::size_t pivot = row;
    while (pivot < m && a(pivot, c) == T(0)) ++pivot;
    if (pivot == m) continue;
    if (pivot != row) {
      for (std::size_t k = 0; k < n; ++k) std::swap(a(pivot, k), a(row, k));
    }
    for (std::size_t r = row + 1; r < m; ++r) {
      // Bareiss: a(r, k) = (a(row, c) a(r, k) - a(r, c) a(row, k)) / previous pivot, exact.
      for (std::size_t k = c + 1; k < n; ++k) a(r, k) = (a(row, c) * a(r, k) - a(r, c) * a(row, k)) / previous;
      a(r, c) = T(0);
    }
    previous = a(row, c);
    ++row;
  }
  return a;
}

template <class T>
vnl_matrix<T> vnl_rank_column_reduce(const vnl_matrix<T>& mat, vnl_rank_pivot_type t = vnl_rank_pivot_all) {
  return vnl_rank_row_reduce(mat.transpose(), t).transpose();
}

template <class T>
vnl_matrix<T> vnl_rank_row_column_reduce(const vnl_matrix<T>& mat, vnl_rank_pivot_type t = vnl_rank_pivot_all) {
  return vnl_rank_column_reduce(vnl_rank_row_reduce(mat, t), t);
}

/// The number of linearly independent rows (= columns); `type` picks the reduction used.
template <class T>
unsigned int vnl_rank(const vnl_matrix<T>& mat, vnl_rank_type type = vnl_rank_both) {
  const vnl_matrix<T> reduced =
      type == vnl_rank_column ? vnl_rank_row_reduce(mat.transpose()) : vnl_rank_row_reduce(mat);
  unsigned int rank = 0;
  for (std::size_t r = 0; r < reduced.rows(); ++r) {
    bool nonzero = false;
    for (std::size_t c = 0; c < reduced.cols() && !nonzero; ++c) nonzero = !(reduced(r, c) == T(0));
    rank += nonzero;
  }
  return rank;
}

}  // inline namespace edgetrack_ports
