// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_index_sort.h: sorts a vector (or each row or column of a
/// matrix) in ascending order and reports the original index of each sorted value.
#pragma once

#ifdef vnl_index_sort_h_
#error "edgetrack's drop-in vnl/vnl_index_sort.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class TValue, class TIndex>
class vnl_index_sort {
 public:
  using SortVectorType = vnl_vector<TValue>;
  using SortVectorIndexType = vnl_vector<TIndex>;
  using SortMatrixType = vnl_matrix<TValue>;
  using SortMatrixIndexType = vnl_matrix<TIndex>;
  enum DirectionType { ByRow, ByColumn };

  /// indices[k] is the index in `values` of the k-th smallest value (stable on ties).
  void vector_sort(const SortVectorType& values, SortVectorIndexType& indices) {
    indices.set_size(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) indices[i] = TIndex(i);
    std::stable_sort(indices.begin(), indices.end(),
                     [&values](const TIndex& a, const TIndex& b) { return values[a] < values[b]; });
  }
  void vector_sort(const SortVectorType& values, SortVectorType& sorted_values, SortVectorIndexType& indices) {
    vector_sort(values, indices);
    sorted_values.set_size(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) sorted_values[i] = values[indices[i]];
  }
  void vector_sort_in_place(SortVectorType& values, SortVectorIndexType& indices) {
    const SortVectorType original(values);
    vector_sort(original, values, indices);
  }
  /// Sorts each row (ByRow) or each column (ByColumn) on its own.
  void matrix_sort(DirectionType direction, const SortMatrixType& values, SortMatrixType& sorted_values,
                   SortMatrixIndexType& indices) {
    sorted_values.set_size(values.rows(), values.cols());
    indices.set_size(values.rows(), values.cols());
    const std::size_t count = direction == ByRow ? values.rows() : values.cols();
    SortVectorType sorted;
    SortVectorIndexType order;
    for (std::size_t k = 0; k < count; ++k) {
      vector_sort(direction == ByRow ? values.get_row(k) : values.get_column(k), sorted, order);
      if (direction == ByRow) {
        sorted_values.set_row(k, sorted);
        indices.set_row(k, order);
      } else {
        sorted_values.set_column(k, sorted);
        indices.set_column(k, order);
      }
    }
  }
};

}  // inline namespace edgetrack_ports
