// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matrix.h: a heap-allocated, row-major matrix of T with vnl's
/// names (rows, cols, set_size, transpose, get_row, set_column, extract, update...).
/// Declarations only; vnl_matrix.hxx defines them, instances/ instantiates them for `real`.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <vector>

#include "vnl/vnl_vector.h"

template <class T>
class vnl_matrix {
 public:
  using element_type = T;

  vnl_matrix() = default;
  vnl_matrix(std::size_t rows, std::size_t cols);
  vnl_matrix(std::size_t rows, std::size_t cols, const T& value);
  /// Copies rows*cols elements from row-major `data`.
  vnl_matrix(const T* data, std::size_t rows, std::size_t cols);

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  std::size_t columns() const { return cols_; }
  std::size_t size() const { return data_.size(); }
  /// Resizes; the contents are zero afterwards.
  bool set_size(std::size_t rows, std::size_t cols);

  T& operator()(std::size_t r, std::size_t c) { return data_[r * cols_ + c]; }
  const T& operator()(std::size_t r, std::size_t c) const { return data_[r * cols_ + c]; }
  /// Row r, as upstream's m[r][c].
  T* operator[](std::size_t r) { return data_.data() + r * cols_; }
  const T* operator[](std::size_t r) const { return data_.data() + r * cols_; }
  T get(std::size_t r, std::size_t c) const { return (*this)(r, c); }
  void put(std::size_t r, std::size_t c, const T& v) { (*this)(r, c) = v; }

  T* data_block() { return data_.data(); }
  const T* data_block() const { return data_.data(); }

  vnl_matrix& fill(const T& value);
  vnl_matrix& fill_diagonal(const T& value);
  /// Makes the matrix the identity (any shape: ones on the main diagonal).
  vnl_matrix& set_identity();
  vnl_matrix& copy_in(const T* data);
  void copy_out(T* data) const;

  vnl_matrix transpose() const;
  /// Transposes in place; a non-square matrix swaps its dimensions.
  vnl_matrix& inplace_transpose();

  vnl_vector<T> get_row(std::size_t r) const;
  vnl_vector<T> get_column(std::size_t c) const;
  vnl_vector<T> get_diagonal() const;
  vnl_matrix& set_row(std::size_t r, const vnl_vector<T>& v);
  vnl_matrix& set_column(std::size_t c, const vnl_vector<T>& v);
  /// The rows x cols block whose top-left corner is (top, left).
  vnl_matrix extract(std::size_t rows, std::size_t cols, std::size_t top = 0, std::size_t left = 0) const;
  /// Writes `m` into this matrix with its top-left corner at (top, left).
  vnl_matrix& update(const vnl_matrix& m, std::size_t top = 0, std::size_t left = 0);

  vnl_matrix& operator+=(const vnl_matrix& rhs);
  vnl_matrix& operator-=(const vnl_matrix& rhs);
  vnl_matrix& operator*=(const T& value);
  vnl_matrix& operator/=(const T& value);
  vnl_matrix operator-() const;

  T frobenius_norm() const;
  T fro_norm() const { return frobenius_norm(); }
  T absolute_value_max() const;
  bool is_identity(const T& tol) const;

  bool operator==(const vnl_matrix& rhs) const {
    return rows_ == rhs.rows_ && cols_ == rhs.cols_ && data_ == rhs.data_;
  }
  bool operator!=(const vnl_matrix& rhs) const { return !(*this == rhs); }

 private:
  std::size_t rows_ = 0;
  std::size_t cols_ = 0;
  std::vector<T> data_;
};

template <class T>
vnl_matrix<T> operator+(vnl_matrix<T> a, const vnl_matrix<T>& b) {
  return a += b;
}
template <class T>
vnl_matrix<T> operator-(vnl_matrix<T> a, const vnl_matrix<T>& b) {
  return a -= b;
}
template <class T>
vnl_matrix<T> operator*(vnl_matrix<T> m, const T& s) {
  return m *= s;
}
template <class T>
vnl_matrix<T> operator*(const T& s, vnl_matrix<T> m) {
  return m *= s;
}
template <class T>
vnl_matrix<T> operator/(vnl_matrix<T> m, const T& s) {
  return m /= s;
}

/// Matrix product a * b.
template <class T>
vnl_matrix<T> operator*(const vnl_matrix<T>& a, const vnl_matrix<T>& b);
/// Matrix-vector product m * v.
template <class T>
vnl_vector<T> operator*(const vnl_matrix<T>& m, const vnl_vector<T>& v);
/// Row vector times matrix, v^T * m.
template <class T>
vnl_vector<T> operator*(const vnl_vector<T>& v, const vnl_matrix<T>& m);
/// Outer product a * b^T.
template <class T>
vnl_matrix<T> outer_product(const vnl_vector<T>& a, const vnl_vector<T>& b);

template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_matrix<T>& m);
