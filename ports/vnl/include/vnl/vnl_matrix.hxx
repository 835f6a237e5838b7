// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_matrix.h (upstream: core/vnl/vnl_matrix.hxx). Include it only to
/// instantiate vnl_matrix for a scalar that the library does not instantiate.
#pragma once

#include <cassert>
#include <cmath>
#include <ostream>
#include <utility>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.hxx"

template <class T>
vnl_matrix<T>::vnl_matrix(std::size_t rows, std::size_t cols) : rows_(rows), cols_(cols), data_(rows * cols, T(0)) {}

template <class T>
vnl_matrix<T>::vnl_matrix(std::size_t rows, std::size_t cols, const T& value)
    : rows_(rows), cols_(cols), data_(rows * cols, value) {}

template <class T>
vnl_matrix<T>::vnl_matrix(const T* data, std::size_t rows, std::size_t cols)
    : rows_(rows), cols_(cols), data_(data, data + rows * cols) {}

template <class T>
bool vnl_matrix<T>::set_size(std::size_t rows, std::size_t cols) {
  rows_ = rows;
  cols_ = cols;
  data_.assign(rows * cols, T(0));
  return true;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::fill(const T& value) {
  for (T& x : data_) x = value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::fill_diagonal(const T& value) {
  for (std::size_t i = 0; i < rows_ && i < cols_; ++i) (*this)(i, i) = value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_identity() {
  fill(T(0));
  return fill_diagonal(T(1));
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::copy_in(const T* data) {
  for (std::size_t i = 0; i < data_.size(); ++i) data_[i] = data[i];
  return *this;
}

template <class T>
void vnl_matrix<T>::copy_out(T* data) const {
  for (std::size_t i = 0; i < data_.size(); ++i) data[i] = data_[i];
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::transpose() const {
  vnl_matrix result(cols_, rows_);
  for (std::size_t r = 0; r < rows_; ++r) {
    for (std::size_t c = 0; c < cols_; ++c) result(c, r) = (*this)(r, c);
  }
  return result;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::inplace_transpose() {
  *this = transpose();
  return *this;
}

template <class T>
vnl_vector<T> vnl_matrix<T>::get_row(std::size_t r) const {
  assert(r < rows_);
  return vnl_vector<T>((*this)[r], cols_);
}

template <class T>
vnl_vector<T> vnl_matrix<T>::get_column(std::size_t c) const {
  assert(c < cols_);
  vnl_vector<T> column(rows_);
  for (std::size_t r = 0; r < rows_; ++r) column[r] = (*this)(r, c);
  return column;
}

template <class T>
vnl_vector<T> vnl_matrix<T>::get_diagonal() const {
  const std::size_t n = rows_ < cols_ ? rows_ : cols_;
  vnl_vector<T> diagonal(n);
  for (std::size_t i = 0; i < n; ++i) diagonal[i] = (*this)(i, i);
  return diagonal;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_row(std::size_t r, const vnl_vector<T>& v) {
  assert(r < rows_ && v.size() == cols_);
  for (std::size_t c = 0; c < cols_; ++c) (*this)(r, c) = v[c];
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_column(std::size_t c, const vnl_vector<T>& v) {
  assert(c < cols_ && v.size() == rows_);
  for (std::size_t r = 0; r < rows_; ++r) (*this)(r, c) = v[r];
  return *this;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::extract(std::size_t rows, std::size_t cols, std::size_t top, std::size_t left) const {
  assert(top + rows <= rows_ && left + cols <= cols_);
  vnl_matrix result(rows, cols);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) result(r, c) = (*this)(top + r, left + c);
  }
  return result;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::update(const vnl_matrix& m, std::size_t top, std::size_t left) {
  assert(top + m.rows_ <= rows_ && left + m.cols_ <= cols_);
  for (std::size_t r = 0; r < m.rows_; ++r) {
    for (std::size_t c = 0; c < m.cols_; ++c) (*this)(top + r, left + c) = m(r, c);
  }
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator+=(const vnl_matrix& rhs) {
  assert(rows_ == rhs.rows_ && cols_ == rhs.cols_);
  for (std::size_t i = 0; i < data_.size(); ++i) data_[i] += rhs.data_[i];
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator-=(const vnl_matrix& rhs) {
  assert(rows_ == rhs.rows_ && cols_ == rhs.cols_);
  for (std::size_t i = 0; i < data_.size(); ++i) data_[i] -= rhs.data_[i];
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator*=(const T& value) {
  for (T& x : data_) x *= value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator/=(const T& value) {
  for (T& x : data_) x /= value;
  return *this;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator-() const {
  vnl_matrix result(rows_, cols_);
  for (std::size_t i = 0; i < data_.size(); ++i) result.data_[i] = -data_[i];
  return result;
}

template <class T>
T vnl_matrix<T>::frobenius_norm() const {
  using std::sqrt;
  T total(0);
  for (const T& x : data_) total += x * x;
  return sqrt(total);
}

template <class T>
T vnl_matrix<T>::absolute_value_max() const {
  using std::abs;
  T largest(0);
  for (const T& x : data_) {
    const T a = abs(x);
    if (a > largest) largest = a;
  }
  return largest;
}

template <class T>
bool vnl_matrix<T>::is_identity(const T& tol) const {
  using std::abs;
  for (std::size_t r = 0; r < rows_; ++r) {
    for (std::size_t c = 0; c < cols_; ++c) {
      const T expected = r == c ? T(1) : T(0);
      if (abs((*this)(r, c) - expected) > tol) return false;
    }
  }
  return true;
}

template <class T>
vnl_matrix<T> operator*(const vnl_matrix<T>& a, const vnl_matrix<T>& b) {
  assert(a.cols() == b.rows());
  vnl_matrix<T> result(a.rows(), b.cols());
  for (std::size_t r = 0; r < a.rows(); ++r) {
    for (std::size_t c = 0; c < b.cols(); ++c) {
      T total(0);
      for (std::size_t k = 0; k < a.cols(); ++k) total += a(r, k) * b(k, c);
      result(r, c) = total;
    }
  }
  return result;
}

template <class T>
vnl_vector<T> operator*(const vnl_matrix<T>& m, const vnl_vector<T>& v) {
  assert(m.cols() == v.size());
  vnl_vector<T> result(m.rows());
  for (std::size_t r = 0; r < m.rows(); ++r) {
    T total(0);
    for (std::size_t c = 0; c < m.cols(); ++c) total += m(r, c) * v[c];
    result[r] = total;
  }
  return result;
}

template <class T>
vnl_vector<T> operator*(const vnl_vector<T>& v, const vnl_matrix<T>& m) {
  assert(m.rows() == v.size());
  vnl_vector<T> result(m.cols());
  for (std::size_t c = 0; c < m.cols(); ++c) {
    T total(0);
    for (std::size_t r = 0; r < m.rows(); ++r) total += v[r] * m(r, c);
    result[c] = total;
  }
  return result;
}

template <class T>
vnl_matrix<T> outer_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  vnl_matrix<T> result(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    for (std::size_t c = 0; c < b.size(); ++c) result(r, c) = a[r] * b[c];
  }
  return result;
}

template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_matrix<T>& m) {
  for (std::size_t r = 0; r < m.rows(); ++r) {
    for (std::size_t c = 0; c < m.cols(); ++c) {
      if (c) s << ' ';
      s << static_cast<double>(m(r, c));
    }
    s << '\n';
  }
  return s;
}

/// Explicitly instantiates vnl_matrix<T> and its free functions (used by instances/).
#define VNL_MATRIX_INSTANTIATE(T)                                                   \
  template class vnl_matrix<T>;                                                     \
  template vnl_matrix<T> operator*(const vnl_matrix<T>&, const vnl_matrix<T>&);     \
  template vnl_vector<T> operator*(const vnl_matrix<T>&, const vnl_vector<T>&);     \
  template vnl_vector<T> operator*(const vnl_vector<T>&, const vnl_matrix<T>&);     \
  template vnl_matrix<T> outer_product(const vnl_vector<T>&, const vnl_vector<T>&); \
  template std::ostream& operator<<(std::ostream&, const vnl_matrix<T>&)
