// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_matrix.h (upstream: core/vnl/vnl_matrix.hxx). Include it only to
/// instantiate vnl_matrix for a scalar that the library does not instantiate.
#pragma once

#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_ref.h"
#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

template <class T>
void vnl_matrix<T>::make_row_pointers() {
  delete[] row_pointers_;
  row_pointers_ = num_rows_ ? new T*[num_rows_] : nullptr;
  for (std::size_t r = 0; r < num_rows_; ++r) row_pointers_[r] = data_ + r * num_cols_;
}

template <class T>
vnl_matrix<T>::vnl_matrix(std::size_t rows, std::size_t cols) : vnl_matrix(rows, cols, T(0)) {}

template <class T>
vnl_matrix<T>::vnl_matrix(std::size_t rows, std::size_t cols, const T& value)
    : data_(rows * cols != 0 ? new T[rows * cols] : nullptr), num_rows_(rows), num_cols_(cols) {
  make_row_pointers();
  fill(value);
}

template <class T>
vnl_matrix<T>::vnl_matrix(std::size_t rows, std::size_t cols, std::size_t n, const T values[])
    : vnl_matrix(rows, cols) {
  for (std::size_t i = 0; i < n && i < size(); ++i) data_[i] = values[i];
}

template <class T>
vnl_matrix<T>::vnl_matrix(std::size_t rows, std::size_t cols, vnl_matrix_type type) : vnl_matrix(rows, cols) {
  if (type == vnl_matrix_identity) set_identity();
}

template <class T>
vnl_matrix<T>::vnl_matrix(const T* data, std::size_t rows, std::size_t cols) : vnl_matrix(rows, cols) {
  copy_in(data);
}

template <class T>
vnl_matrix<T>::vnl_matrix(std::initializer_list<std::initializer_list<T>> rows)
    : vnl_matrix(rows.size(), rows.size() ? rows.begin()->size() : 0) {
  std::size_t r = 0;
  for (const auto& row : rows) {
    assert(row.size() == num_cols_);
    std::size_t c = 0;
    for (const T& x : row) (*this)(r, c++) = x;
    ++r;
  }
}

template <class T>
vnl_matrix<T>::vnl_matrix(std::size_t rows, std::size_t cols, T* data, bool manage_own_memory)
    : data_(data), num_rows_(rows), num_cols_(cols), own_memory_(manage_own_memory) {
  make_row_pointers();
}

template <class T>
vnl_matrix<T>::vnl_matrix(const vnl_matrix& that) : vnl_matrix(that.data_, that.num_rows_, that.num_cols_) {}

template <class T>
vnl_matrix<T>::vnl_matrix(vnl_matrix&& that) noexcept : vnl_matrix() {
  if (that.own_memory_) {
    swap(that);
  } else {
    *this = that;
  }
}

template <class T>
vnl_matrix<T>::~vnl_matrix() {
  destroy();
}

template <class T>
void vnl_matrix<T>::destroy() {
  if (own_memory_) delete[] data_;
  delete[] row_pointers_;
  data_ = nullptr;
  row_pointers_ = nullptr;
  num_rows_ = num_cols_ = 0;
  own_memory_ = true;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator=(const vnl_matrix& rhs) {
  if (this == &rhs) return *this;
  if (num_rows_ != rhs.num_rows_ || num_cols_ != rhs.num_cols_) {
    assert(own_memory_ && "a vnl_matrix_ref cannot change size");
    set_size(rhs.num_rows_, rhs.num_cols_);
  }
  return copy_in(rhs.data_);
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator=(vnl_matrix&& rhs) {
  if (this == &rhs) return *this;
  if (own_memory_ && rhs.own_memory_) {
    swap(rhs);
    return *this;
  }
  return *this = static_cast<const vnl_matrix&>(rhs);
}

template <class T>
bool vnl_matrix<T>::set_size(std::size_t rows, std::size_t cols) {
  if (!own_memory_) {
    assert(rows == num_rows_ && cols == num_cols_ && "a vnl_matrix_ref cannot change size");
    return rows == num_rows_ && cols == num_cols_;
  }
  if (rows * cols != size()) {
    delete[] data_;
    data_ = rows * cols != 0 ? new T[rows * cols] : nullptr;
  }
  num_rows_ = rows;
  num_cols_ = cols;
  make_row_pointers();
  fill(T(0));
  return true;
}

template <class T>
void vnl_matrix<T>::clear() {
  if (own_memory_) destroy();
}

template <class T>
void vnl_matrix<T>::swap(vnl_matrix& that) noexcept {
  std::swap(data_, that.data_);
  std::swap(row_pointers_, that.row_pointers_);
  std::swap(num_rows_, that.num_rows_);
  std::swap(num_cols_, that.num_cols_);
  std::swap(own_memory_, that.own_memory_);
}

template <class T>
vnl_matrix_ref<T> vnl_matrix<T>::as_ref() {
  return vnl_matrix_ref<T>(num_rows_, num_cols_, data_);
}

template <class T>
const vnl_matrix_ref<T> vnl_matrix<T>::as_ref() const {
  return vnl_matrix_ref<T>(num_rows_, num_cols_, const_cast<T*>(data_));
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::fill(const T& value) {
  for (T& x : *this) x = value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::fill_diagonal(const T& value) {
  for (std::size_t i = 0; i < num_rows_ && i < num_cols_; ++i) (*this)(i, i) = value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_diagonal(const vnl_vector<T>& v) {
  assert(v.size() <= num_rows_ && v.size() <= num_cols_);
  for (std::size_t i = 0; i < v.size(); ++i) (*this)(i, i) = v[i];
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_identity() {
  fill(T(0));
  return fill_diagonal(T(1));
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::copy_in(const T* data) {
  for (std::size_t i = 0; i < size(); ++i) data_[i] = data[i];
  return *this;
}

template <class T>
void vnl_matrix<T>::copy_out(T* data) const {
  for (std::size_t i = 0; i < size(); ++i) data[i] = data_[i];
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator+=(T value) {
  for (T& x : *this) x += value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator-=(T value) {
  for (T& x : *this) x -= value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator*=(T value) {
  for (T& x : *this) x *= value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator/=(T value) {
  for (T& x : *this) x /= value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator+=(const vnl_matrix& rhs) {
  assert(num_rows_ == rhs.num_rows_ && num_cols_ == rhs.num_cols_);
  for (std::size_t i = 0; i < size(); ++i) data_[i] += rhs.data_[i];
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::operator-=(const vnl_matrix& rhs) {
  assert(num_rows_ == rhs.num_rows_ && num_cols_ == rhs.num_cols_);
  for (std::size_t i = 0; i < size(); ++i) data_[i] -= rhs.data_[i];
  return *this;
}

template <class T>
vnl_matrix<typename vnl_numeric_traits<T>::signed_t> vnl_matrix<T>::operator-() const {
  using signed_t = typename vnl_numeric_traits<T>::signed_t;
  vnl_matrix<signed_t> result(num_rows_, num_cols_);
  signed_t* out = result.data_block();
  for (std::size_t i = 0; i < size(); ++i) out[i] = -static_cast<signed_t>(data_[i]);
  return result;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator+(const T& v) const {
  vnl_matrix result(*this);
  return result += v;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator-(const T& v) const {
  vnl_matrix result(*this);
  return result -= v;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator*(const T& v) const {
  vnl_matrix result(*this);
  return result *= v;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator/(const T& v) const {
  vnl_matrix result(*this);
  return result /= v;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator+(const vnl_matrix& rhs) const {
  vnl_matrix result(*this);
  return result += rhs;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator-(const vnl_matrix& rhs) const {
  vnl_matrix result(*this);
  return result -= rhs;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::operator*(const vnl_matrix& b) const {
  assert(num_cols_ == b.num_rows_);
  vnl_matrix result(num_rows_, b.num_cols_);
  for (std::size_t r = 0; r < num_rows_; ++r) {
    for (std::size_t c = 0; c < b.num_cols_; ++c) {
      T total(0);
      for (std::size_t k = 0; k < num_cols_; ++k) total += (*this)(r, k) * b(k, c);
      result(r, c) = total;
    }
  }
  return result;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::apply(T (*f)(T)) const {
  vnl_matrix result(num_rows_, num_cols_);
  for (std::size_t i = 0; i < size(); ++i) result.data_[i] = f(data_[i]);
  return result;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::apply(T (*f)(const T&)) const {
  vnl_matrix result(num_rows_, num_cols_);
  for (std::size_t i = 0; i < size(); ++i) result.data_[i] = f(data_[i]);
  return result;
}

template <class T>
vnl_vector<T> vnl_matrix<T>::apply_rowwise(T (*f)(const vnl_vector<T>&)) const {
  vnl_vector<T> result(num_rows_);
  for (std::size_t r = 0; r < num_rows_; ++r) result[r] = f(get_row(r));
  return result;
}

template <class T>
vnl_vector<T> vnl_matrix<T>::apply_columnwise(T (*f)(const vnl_vector<T>&)) const {
  vnl_vector<T> result(num_cols_);
  for (std::size_t c = 0; c < num_cols_; ++c) result[c] = f(get_column(c));
  return result;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::transpose() const {
  vnl_matrix result(num_cols_, num_rows_);
  for (std::size_t r = 0; r < num_rows_; ++r) {
    for (std::size_t c = 0; c < num_cols_; ++c) result(c, r) = (*this)(r, c);
  }
  return result;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::conjugate_transpose() const {
  vnl_matrix result(num_cols_, num_rows_);
  for (std::size_t r = 0; r < num_rows_; ++r) {
    for (std::size_t c = 0; c < num_cols_; ++c) result(c, r) = vnl_math::conj((*this)(r, c));
  }
  return result;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::inplace_transpose() {
  const vnl_matrix transposed = transpose();
  if (own_memory_) {
    *this = transposed;
  } else {  // a view keeps its block: same elements, rows and columns swapped
    num_rows_ = transposed.num_rows_;
    num_cols_ = transposed.num_cols_;
    make_row_pointers();
    copy_in(transposed.data_);
  }
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::update(const vnl_matrix& m, std::size_t top, std::size_t left) {
  assert(top + m.num_rows_ <= num_rows_ && left + m.num_cols_ <= num_cols_);
  for (std::size_t r = 0; r < m.num_rows_; ++r) {
    for (std::size_t c = 0; c < m.num_cols_; ++c) (*this)(top + r, left + c) = m(r, c);
  }
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_column(std::size_t c, const T* v) {
  for (std::size_t r = 0; r < num_rows_; ++r) (*this)(r, c) = v[r];
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_column(std::size_t c, T value) {
  for (std::size_t r = 0; r < num_rows_; ++r) (*this)(r, c) = value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_column(std::size_t c, const vnl_vector<T>& v) {
  assert(c < num_cols_ && v.size() == num_rows_);
  return set_column(c, v.data_block());
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_columns(std::size_t starting_column, const vnl_matrix& m) {
  assert(m.num_rows_ == num_rows_ && starting_column + m.num_cols_ <= num_cols_);
  return update(m, 0, starting_column);
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_row(std::size_t r, const T* v) {
  for (std::size_t c = 0; c < num_cols_; ++c) (*this)(r, c) = v[c];
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_row(std::size_t r, T value) {
  for (std::size_t c = 0; c < num_cols_; ++c) (*this)(r, c) = value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::set_row(std::size_t r, const vnl_vector<T>& v) {
  assert(r < num_rows_ && v.size() == num_cols_);
  return set_row(r, v.data_block());
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::extract(std::size_t rows, std::size_t cols, std::size_t top, std::size_t left) const {
  vnl_matrix result(rows, cols);
  extract(result, top, left);
  return result;
}

template <class T>
void vnl_matrix<T>::extract(vnl_matrix& sub_matrix, std::size_t top, std::size_t left) const {
  assert(top + sub_matrix.num_rows_ <= num_rows_ && left + sub_matrix.num_cols_ <= num_cols_);
  for (std::size_t r = 0; r < sub_matrix.num_rows_; ++r) {
    for (std::size_t c = 0; c < sub_matrix.num_cols_; ++c) sub_matrix(r, c) = (*this)(top + r, left + c);
  }
}

template <class T>
vnl_vector<T> vnl_matrix<T>::get_row(std::size_t r) const {
  assert(r < num_rows_);
  return vnl_vector<T>((*this)[r], num_cols_);
}

template <class T>
vnl_vector<T> vnl_matrix<T>::get_column(std::size_t c) const {
  assert(c < num_cols_);
  vnl_vector<T> column(num_rows_);
  for (std::size_t r = 0; r < num_rows_; ++r) column[r] = (*this)(r, c);
  return column;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::get_rows(const vnl_vector<unsigned int>& i) const {
  vnl_matrix result(i.size(), num_cols_);
  for (std::size_t k = 0; k < i.size(); ++k) result.set_row(k, (*this)[i[k]]);
  return result;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::get_columns(const vnl_vector<unsigned int>& i) const {
  vnl_matrix result(num_rows_, i.size());
  for (std::size_t k = 0; k < i.size(); ++k) result.set_column(k, get_column(i[k]));
  return result;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::get_n_rows(std::size_t rowstart, std::size_t n) const {
  return extract(n, num_cols_, rowstart, 0);
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::get_n_columns(std::size_t colstart, std::size_t n) const {
  return extract(num_rows_, n, 0, colstart);
}

template <class T>
vnl_vector<T> vnl_matrix<T>::get_diagonal() const {
  const std::size_t n = num_rows_ < num_cols_ ? num_rows_ : num_cols_;
  vnl_vector<T> diagonal(n);
  for (std::size_t i = 0; i < n; ++i) diagonal[i] = (*this)(i, i);
  return diagonal;
}

template <class T>
vnl_vector<T> vnl_matrix<T>::flatten_row_major() const {
  return vnl_vector<T>(data_, size());
}

template <class T>
vnl_vector<T> vnl_matrix<T>::flatten_column_major() const {
  return transpose().flatten_row_major();
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::flipud() {
  for (std::size_t top = 0, bottom = num_rows_; top + 1 < bottom; ++top, --bottom) {
    for (std::size_t c = 0; c < num_cols_; ++c) std::swap((*this)(top, c), (*this)(bottom - 1, c));
  }
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::fliplr() {
  for (std::size_t left = 0, right = num_cols_; left + 1 < right; ++left, --right) {
    for (std::size_t r = 0; r < num_rows_; ++r) std::swap((*this)(r, left), (*this)(r, right - 1));
  }
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::normalize_rows() {
  for (std::size_t r = 0; r < num_rows_; ++r) {
    abs_t total(0);
    for (std::size_t c = 0; c < num_cols_; ++c) total += abs_t(vnl_math::squared_magnitude((*this)(r, c)));
    if (total == abs_t(0)) continue;
    const abs_t norm = vnl_detail::root(total);
    for (std::size_t c = 0; c < num_cols_; ++c) (*this)(r, c) = T((*this)(r, c) / norm);
  }
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::normalize_columns() {
  for (std::size_t c = 0; c < num_cols_; ++c) {
    abs_t total(0);
    for (std::size_t r = 0; r < num_rows_; ++r) total += abs_t(vnl_math::squared_magnitude((*this)(r, c)));
    if (total == abs_t(0)) continue;
    const abs_t norm = vnl_detail::root(total);
    for (std::size_t r = 0; r < num_rows_; ++r) (*this)(r, c) = T((*this)(r, c) / norm);
  }
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::scale_row(std::size_t row, T value) {
  for (std::size_t c = 0; c < num_cols_; ++c) (*this)(row, c) *= value;
  return *this;
}

template <class T>
vnl_matrix<T>& vnl_matrix<T>::scale_column(std::size_t col, T value) {
  for (std::size_t r = 0; r < num_rows_; ++r) (*this)(r, col) *= value;
  return *this;
}

template <class T>
typename vnl_matrix<T>::abs_t vnl_matrix<T>::array_one_norm() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).one_norm();
}

template <class T>
typename vnl_matrix<T>::abs_t vnl_matrix<T>::array_two_norm() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).two_norm();
}

template <class T>
typename vnl_matrix<T>::abs_t vnl_matrix<T>::array_inf_norm() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).inf_norm();
}

template <class T>
typename vnl_matrix<T>::abs_t vnl_matrix<T>::operator_one_norm() const {
  abs_t largest(0);
  for (std::size_t c = 0; c < num_cols_; ++c) {
    abs_t total(0);
    for (std::size_t r = 0; r < num_rows_; ++r) total += abs_t(vnl_math::abs((*this)(r, c)));
    if (total > largest) largest = total;
  }
  return largest;
}

template <class T>
typename vnl_matrix<T>::abs_t vnl_matrix<T>::operator_inf_norm() const {
  abs_t largest(0);
  for (std::size_t r = 0; r < num_rows_; ++r) {
    abs_t total(0);
    for (std::size_t c = 0; c < num_cols_; ++c) total += abs_t(vnl_math::abs((*this)(r, c)));
    if (total > largest) largest = total;
  }
  return largest;
}

template <class T>
typename vnl_matrix<T>::abs_t vnl_matrix<T>::rms() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).rms();
}

template <class T>
T vnl_matrix<T>::min_value() const {
  return data_[arg_min()];
}

template <class T>
T vnl_matrix<T>::max_value() const {
  return data_[arg_max()];
}

template <class T>
std::size_t vnl_matrix<T>::arg_min() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).arg_min();
}

template <class T>
std::size_t vnl_matrix<T>::arg_max() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).arg_max();
}

template <class T>
T vnl_matrix<T>::mean() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).mean();
}

template <class T>
bool vnl_matrix<T>::is_identity() const {
  for (std::size_t r = 0; r < num_rows_; ++r) {
    for (std::size_t c = 0; c < num_cols_; ++c) {
      if (!((*this)(r, c) == (r == c ? T(1) : T(0)))) return false;
    }
  }
  return true;
}

template <class T>
bool vnl_matrix<T>::is_identity(double tol) const {
  for (std::size_t r = 0; r < num_rows_; ++r) {
    for (std::size_t c = 0; c < num_cols_; ++c) {
      const T expected = r == c ? T(1) : T(0);
      if (static_cast<double>(vnl_math::abs((*this)(r, c) - expected)) > tol) return false;
    }
  }
  return true;
}

template <class T>
bool vnl_matrix<T>::is_zero() const {
  for (const T& x : *this) {
    if (!(x == T(0))) return false;
  }
  return true;
}

template <class T>
bool vnl_matrix<T>::is_zero(double tol) const {
  for (const T& x : *this) {
    if (static_cast<double>(vnl_math::abs(x)) > tol) return false;
  }
  return true;
}

template <class T>
bool vnl_matrix<T>::is_equal(const vnl_matrix& rhs, double tol) const {
  if (rhs.num_rows_ != num_rows_ || rhs.num_cols_ != num_cols_) return false;
  for (std::size_t i = 0; i < size(); ++i) {
    if (!(static_cast<double>(vnl_math::abs(data_[i] - rhs.data_[i])) <= tol)) return false;  // NaN is unequal
  }
  return true;
}

template <class T>
bool vnl_matrix<T>::is_finite() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).is_finite();
}

template <class T>
bool vnl_matrix<T>::has_nans() const {
  return vnl_vector_ref<T>(size(), const_cast<T*>(data_)).has_nans();
}

template <class T>
void vnl_matrix<T>::assert_size(std::size_t r, std::size_t c) const {
  if (r != num_rows_ || c != num_cols_) {
    std::fprintf(stderr, "vnl_matrix: size is %zu x %zu, expected %zu x %zu\n", num_rows_, num_cols_, r, c);
    std::abort();
  }
}

template <class T>
void vnl_matrix<T>::assert_finite() const {
  if (!is_finite()) {
    std::fprintf(stderr, "vnl_matrix: an element is not finite\n");
    std::abort();
  }
}

template <class T>
bool vnl_matrix<T>::operator_eq(const vnl_matrix& rhs) const {
  if (rhs.num_rows_ != num_rows_ || rhs.num_cols_ != num_cols_) return false;
  for (std::size_t i = 0; i < size(); ++i) {
    if (!(data_[i] == rhs.data_[i])) return false;
  }
  return true;
}

template <class T>
bool vnl_matrix<T>::read_ascii(std::istream& s) {
  if (!empty()) {
    for (T& x : *this) {
      if (!vnl_detail::read_element(s, x)) return false;
    }
    return true;
  }
  // Unsized: each non-empty line is a row; all rows must have as many values as the first.
  std::vector<T> values;
  std::size_t rows = 0, cols = 0;
  std::string line;
  while (std::getline(s, line)) {
    std::istringstream row(line);
    std::size_t count = 0;
    T x;
    while (vnl_detail::read_element(row, x)) {
      values.push_back(x);
      ++count;
    }
    if (count == 0) continue;
    if (rows == 0) cols = count;
    if (count != cols) return false;
    ++rows;
  }
  set_size(rows, cols);
  copy_in(values.data());
  return true;
}

template <class T>
vnl_matrix<T> vnl_matrix<T>::read(std::istream& s) {
  vnl_matrix result;
  result.read_ascii(s);
  return result;
}

template <class T>
void vnl_matrix<T>::print(std::ostream& os) const {
  os << *this;
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
vnl_matrix<T> outer_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  vnl_matrix<T> result(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    for (std::size_t c = 0; c < b.size(); ++c) result(r, c) = a[r] * b[c];
  }
  return result;
}

template <class T>
vnl_matrix<T> element_product(const vnl_matrix<T>& a, const vnl_matrix<T>& b) {
  assert(a.rows() == b.rows() && a.cols() == b.cols());
  vnl_matrix<T> result(a.rows(), a.cols());
  for (std::size_t i = 0; i < a.size(); ++i) result.data_block()[i] = a.data_block()[i] * b.data_block()[i];
  return result;
}

template <class T>
vnl_matrix<T> element_quotient(const vnl_matrix<T>& a, const vnl_matrix<T>& b) {
  assert(a.rows() == b.rows() && a.cols() == b.cols());
  vnl_matrix<T> result(a.rows(), a.cols());
  for (std::size_t i = 0; i < a.size(); ++i) result.data_block()[i] = a.data_block()[i] / b.data_block()[i];
  return result;
}

template <class T>
T dot_product(const vnl_matrix<T>& a, const vnl_matrix<T>& b) {
  assert(a.rows() == b.rows() && a.cols() == b.cols());
  return dot_product(a.flatten_row_major(), b.flatten_row_major());
}

template <class T>
T inner_product(const vnl_matrix<T>& a, const vnl_matrix<T>& b) {
  assert(a.rows() == b.rows() && a.cols() == b.cols());
  return inner_product(a.flatten_row_major(), b.flatten_row_major());
}

template <class T>
T cos_angle(const vnl_matrix<T>& a, const vnl_matrix<T>& b) {
  using abs_t = typename vnl_numeric_traits<T>::abs_t;
  const abs_t norms = a.fro_norm() * b.fro_norm();
  return T(inner_product(a, b) / norms);
}

template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_matrix<T>& m) {
  for (std::size_t r = 0; r < m.rows(); ++r) {
    for (std::size_t c = 0; c < m.cols(); ++c) {
      if (c) s << ' ';
      vnl_detail::print_element(s, m(r, c));
    }
    s << '\n';
  }
  return s;
}

template <class T>
std::istream& operator>>(std::istream& s, vnl_matrix<T>& m) {
  m.read_ascii(s);
  return s;
}

/// Explicitly instantiates vnl_matrix<T> and its free functions (used by instances/).
#define VNL_MATRIX_INSTANTIATE(T)                                                     \
  template class vnl_matrix<T>;                                                       \
  template vnl_vector<T> operator*(const vnl_matrix<T>&, const vnl_vector<T>&);       \
  template vnl_matrix<T> outer_product(const vnl_vector<T>&, const vnl_vector<T>&);   \
  template vnl_matrix<T> element_product(const vnl_matrix<T>&, const vnl_matrix<T>&); \
  template vnl_matrix<T> element_quotient(const vnl_matrix<T>&, const vnl_matrix<T>&); \
  template T dot_product(const vnl_matrix<T>&, const vnl_matrix<T>&);                 \
  template T inner_product(const vnl_matrix<T>&, const vnl_matrix<T>&);               \
  template T cos_angle(const vnl_matrix<T>&, const vnl_matrix<T>&);                   \
  template std::ostream& operator<<(std::ostream&, const vnl_matrix<T>&);             \
  template std::istream& operator>>(std::istream&, vnl_matrix<T>&)

}  // inline namespace edgetrack_ports
