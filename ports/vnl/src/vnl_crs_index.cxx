// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_crs_index.h"

#include <algorithm>

inline namespace edgetrack_ports {

vnl_crs_index::vnl_crs_index(const std::vector<std::vector<bool>>& mask)
    : num_cols_(mask.empty() ? 0 : static_cast<unsigned>(mask[0].size())), row_ptr_(mask.size() + 1, 0) {
  for (std::size_t i = 0; i < mask.size(); ++i) {
    row_ptr_[i] = static_cast<int>(col_idx_.size());
    for (unsigned j = 0; j < num_cols_; ++j) {
      if (mask[i][j]) col_idx_.push_back(static_cast<int>(j));
    }
  }
  row_ptr_[mask.size()] = static_cast<int>(col_idx_.size());
}

int vnl_crs_index::operator()(int i, int j) const {
  const auto first = col_idx_.begin() + row_ptr_[i], last = col_idx_.begin() + row_ptr_[i + 1];
  const auto it = std::lower_bound(first, last, j);  // each row's columns are ascending
  return (it != last && *it == j) ? static_cast<int>(it - col_idx_.begin()) : -1;
}

vnl_crs_index::sparse_vector vnl_crs_index::sparse_row(int i) const {
  sparse_vector row;
  for (int k = row_ptr_[i]; k < row_ptr_[i + 1]; ++k) row.emplace_back(k, col_idx_[k]);
  return row;
}

vnl_crs_index::sparse_vector vnl_crs_index::sparse_col(int j) const {
  sparse_vector column;
  for (int i = 0; i < num_rows(); ++i) {
    const int k = (*this)(i, j);
    if (k >= 0) column.emplace_back(k, i);
  }
  return column;
}

}  // inline namespace edgetrack_ports
