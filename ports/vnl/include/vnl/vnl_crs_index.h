// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_crs_index.h: compressed-row indexing of a sparse pattern. Each
/// nonzero of a boolean mask gets an index 0..num_non_zero()-1, row by row; operator()(i, j)
/// is that index, or -1 where the mask is false.
#pragma once

#ifdef vnl_crs_index_h_
#error "edgetrack's drop-in vnl/vnl_crs_index.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <utility>
#include <vector>

inline namespace edgetrack_ports {

class vnl_crs_index {
 public:
  /// (index, column) for sparse_row, (index, row) for sparse_col.
  using idx_pair = std::pair<int, int>;
  using sparse_vector = std::vector<idx_pair>;

  vnl_crs_index() = default;
  /// mask[i][j] marks element (i, j) as nonzero; every row has the same length.
  explicit vnl_crs_index(const std::vector<std::vector<bool>>& mask);

  int num_rows() const { return static_cast<int>(row_ptr_.size()) - 1; }
  int num_cols() const { return static_cast<int>(num_cols_); }
  int num_non_zero() const { return static_cast<int>(col_idx_.size()); }
  sparse_vector sparse_row(int i) const;
  sparse_vector sparse_col(int j) const;
  int operator()(int i, int j) const;

 private:
  unsigned int num_cols_ = 0;
  std::vector<int> col_idx_;
  std::vector<int> row_ptr_ = std::vector<int>(1, 0);
};

}  // inline namespace edgetrack_ports
