// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_sparse_matrix.h: a sparse matrix kept as one list per row of
/// (column, value) pairs sorted by column. Reading an absent element gives zero; writing
/// through operator() inserts it. Products with vectors, sums, products of sparse matrices,
/// transposes and upstream's row iteration (reset / next / getrow / getcolumn / value).
#pragma once

#ifdef vnl_sparse_matrix_h_
#error "edgetrack's drop-in vnl/vnl_sparse_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>
#include <vector>

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

/// One stored element: `first` is its column, `second` its value.
template <class T>
class vnl_sparse_matrix_pair {
 public:
  unsigned int first = 0;
  T second = T(0);

  vnl_sparse_matrix_pair() = default;
  vnl_sparse_matrix_pair(unsigned int column, const T& value) : first(column), second(value) {}
  bool operator==(const vnl_sparse_matrix_pair& o) const { return first == o.first && second == o.second; }
  /// Orders by column.
  struct less {
    bool operator()(const vnl_sparse_matrix_pair& a, const vnl_sparse_matrix_pair& b) const {
      return a.first < b.first;
    }
  };
};

template <class T>
class vnl_sparse_matrix {
 public:
  using pair_t = vnl_sparse_matrix_pair<T>;
  using row = std::vector<pair_t>;
  using vnl_sparse_matrix_elements = std::vector<row>;

  vnl_sparse_matrix() = default;
  /// An m x n matrix with no stored elements.
  vnl_sparse_matrix(unsigned int m, unsigned int n) : elements_(m), rs_(m), cs_(n) {}

  unsigned int rows() const { return rs_; }
  unsigned int columns() const { return cs_; }
  unsigned int cols() const { return cs_; }
  /// Stored element (row, column), inserted as zero if absent.
  T& operator()(unsigned int r, unsigned int c);
  /// Element (row, column), zero if absent (nothing is inserted).
  T operator()(unsigned int r, unsigned int c) const { return get(r, c); }
  T get(unsigned int r, unsigned int c) const;
  void put(unsigned int r, unsigned int c, T value) { (*this)(r, c) = value; }
  bool empty_row(unsigned int r) const { return elements_[r].empty(); }
  row& get_row(unsigned int r) { return elements_[r]; }
  const row& get_row(unsigned int r) const { return elements_[r]; }
  /// Replaces row r by the given columns and values.
  vnl_sparse_matrix& set_row(unsigned int r, const std::vector<int>& cols, const std::vector<T>& vals);
  T sum_row(unsigned int r);
  void scale_row(unsigned int r, T scale);
  /// Appends the rows of A (same number of columns) below this matrix.
  vnl_sparse_matrix& vcat(const vnl_sparse_matrix& a);
  void clear() { elements_.clear(), rs_ = cs_ = 0; }
  /// Resizes, dropping every stored element.
  void set_size(int r, int c);
  /// Resizes, keeping the stored elements that still fit.
  void resize(int r, int c);

  /// result = this * rhs.
  void mult(const vnl_vector<T>& rhs, vnl_vector<T>& result) const;
  /// q = this * p, p a dense n x m block with n == columns(), q rows() x m, both column-major
  /// (element (i, j) at [i + j * rows of that block]), as upstream.
  void mult(unsigned int n, unsigned int m, const T* p, T* q) const;
  /// result = lhs^T * this.
  void pre_mult(const vnl_vector<T>& lhs, vnl_vector<T>& result) const;
  /// result = this * rhs, this + rhs, this - rhs.
  void mult(const vnl_sparse_matrix& rhs, vnl_sparse_matrix& result) const;
  void add(const vnl_sparse_matrix& rhs, vnl_sparse_matrix& result) const;
  void subtract(const vnl_sparse_matrix& rhs, vnl_sparse_matrix& result) const;
  /// The diagonal of A^T A.
  void diag_AtA(vnl_vector<T>& result) const;

  vnl_vector<T> operator*(const vnl_vector<T>& rhs) const;
  vnl_sparse_matrix operator-() const;
  vnl_sparse_matrix operator+(const vnl_sparse_matrix& rhs) const;
  vnl_sparse_matrix operator-(const vnl_sparse_matrix& rhs) const;
  vnl_sparse_matrix operator*(const vnl_sparse_matrix& rhs) const;
  vnl_sparse_matrix& operator+=(const vnl_sparse_matrix& rhs) { return *this = *this + rhs; }
  vnl_sparse_matrix& operator-=(const vnl_sparse_matrix& rhs) { return *this = *this - rhs; }
  vnl_sparse_matrix& operator*=(const vnl_sparse_matrix& rhs) { return *this = *this * rhs; }
  vnl_sparse_matrix operator*(const T& rhs) const;
  vnl_sparse_matrix& operator*=(const T& rhs);
  vnl_sparse_matrix operator/(const T& rhs) const;
  vnl_sparse_matrix& operator/=(const T& rhs);
  bool operator==(const vnl_sparse_matrix& rhs) const;
  bool operator!=(const vnl_sparse_matrix& rhs) const { return !(*this == rhs); }

  vnl_sparse_matrix transpose() const;
  vnl_sparse_matrix conjugate_transpose() const;
  /// Square only: the identity.
  vnl_sparse_matrix& set_identity();
  /// Scales each non-empty row to unit two-norm.
  vnl_sparse_matrix& normalize_rows();

  /// Iteration over the stored elements, row by row: reset(), then while (next()) read
  /// getrow(), getcolumn() and value().
  void reset() const;
  bool next() const;
  int getrow() const;
  int getcolumn() const;
  T value() const;

 private:
  vnl_sparse_matrix_elements elements_;
  unsigned int rs_ = 0;
  unsigned int cs_ = 0;
  // Iteration cursor (upstream keeps it in the matrix too).
  mutable unsigned int itr_row_ = 0;
  mutable std::size_t itr_index_ = 0;
  mutable bool itr_is_reset_ = true;
};

template <class T>
vnl_sparse_matrix<T> operator*(const T& value, const vnl_sparse_matrix<T>& m) {
  return m * value;
}

}  // inline namespace edgetrack_ports
