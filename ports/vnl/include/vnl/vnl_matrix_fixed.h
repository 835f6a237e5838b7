// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matrix_fixed.h: an r x c matrix of T held by value, row-major,
/// with vnl_matrix's names, and its products with vnl_vector_fixed. Header-only.
#pragma once

#ifdef vnl_matrix_fixed_h_
#error "edgetrack's drop-in vnl/vnl_matrix_fixed.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <cmath>
#include <cstddef>
#include <utility>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_ref.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T, unsigned int num_rows, unsigned int num_cols>
class vnl_matrix_fixed {
 public:
  using element_type = T;
  using self = vnl_matrix_fixed;
  using size_type = std::size_t;
  using iterator = T*;
  using const_iterator = const T*;
  using abs_t = typename vnl_matrix<T>::abs_t;

  /// All zeros (upstream leaves it uninitialised).
  vnl_matrix_fixed() { fill(T(0)); }
  /// Upstream's shape-checked form for code generic over vnl_matrix: the sizes must match.
  vnl_matrix_fixed(unsigned rows, unsigned cols) : vnl_matrix_fixed() {
    assert(rows == num_rows && cols == num_cols);
    (void)rows;
    (void)cols;
  }
  explicit vnl_matrix_fixed(const T& value) { fill(value); }
  /// From row-major data.
  explicit vnl_matrix_fixed(const T* data) { copy_in(data); }
  /// Implicit, as upstream's: a dense matrix of the same shape converts.
  vnl_matrix_fixed(const vnl_matrix<T>& m) {
    assert(m.rows() == num_rows && m.cols() == num_cols);
    copy_in(m.data_block());
  }
  /// Every element set to `value`, as upstream's.
  vnl_matrix_fixed& operator=(const T& value) { return fill(value); }
  /// Copies a dense matrix of the same shape, as upstream's assignment.
  vnl_matrix_fixed& operator=(const vnl_matrix<T>& m) {
    assert(m.rows() == num_rows && m.cols() == num_cols);
    return copy_in(m.data_block());
  }
  vnl_matrix_fixed(const vnl_matrix_fixed&) = default;
  vnl_matrix_fixed& operator=(const vnl_matrix_fixed&) = default;

  static constexpr std::size_t rows() { return num_rows; }
  static constexpr std::size_t cols() { return num_cols; }
  static constexpr std::size_t columns() { return num_cols; }
  static constexpr std::size_t size() { return num_rows * num_cols; }

  T& operator()(std::size_t r, std::size_t c) { return data_[r][c]; }
  const T& operator()(std::size_t r, std::size_t c) const { return data_[r][c]; }
  T* operator[](std::size_t r) { return data_[r]; }
  const T* operator[](std::size_t r) const { return data_[r]; }
  T get(std::size_t r, std::size_t c) const { return data_[r][c]; }
  void put(std::size_t r, std::size_t c, const T& v) { data_[r][c] = v; }
  vnl_matrix_fixed& set(unsigned r, unsigned c, const T& v) {
    data_[r][c] = v;
    return *this;
  }
  T* data_block() { return data_[0]; }
  const T* data_block() const { return data_[0]; }
  iterator begin() { return data_[0]; }
  iterator end() { return data_[0] + size(); }
  const_iterator begin() const { return data_[0]; }
  const_iterator end() const { return data_[0] + size(); }
  static constexpr bool empty() { return num_rows == 0 && num_cols == 0; }

  vnl_matrix_fixed& fill(const T& value) {
    for (auto& row : data_) {
      for (T& x : row) x = value;
    }
    return *this;
  }
  vnl_matrix_fixed& set_identity() {
    fill(T(0));
    for (unsigned i = 0; i < num_rows && i < num_cols; ++i) data_[i][i] = T(1);
    return *this;
  }
  vnl_matrix_fixed& copy_in(const T* data) {
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = 0; c < num_cols; ++c) data_[r][c] = data[r * num_cols + c];
    }
    return *this;
  }
  vnl_matrix_fixed& set(const T* data) { return copy_in(data); }
  void copy_out(T* data) const {
    for (unsigned i = 0; i < size(); ++i) data[i] = data_block()[i];
  }
  /// A heap copy, for code written against vnl_matrix.
  vnl_matrix<T> as_matrix() const { return vnl_matrix<T>(data_block(), num_rows, num_cols); }
  /// A vnl_matrix viewing this matrix's elements (valid while this matrix lives).
  vnl_matrix_ref<T> as_ref() { return vnl_matrix_ref<T>(num_rows, num_cols, data_block()); }
  const vnl_matrix_ref<T> as_ref() const {
    return vnl_matrix_ref<T>(num_rows, num_cols, const_cast<T*>(data_block()));
  }
  /// As upstream's default (VXL_USE_HISTORICAL_IMPLICIT_CONVERSIONS): a fixed matrix passes
  /// where a const vnl_matrix& is expected, as a view of its elements.
  operator const vnl_matrix_ref<T>() const { return as_ref(); }
  explicit operator vnl_matrix<T>() const { return as_matrix(); }
  /// The element-wise norms, as vnl_matrix's.
  typename vnl_matrix<T>::abs_t array_one_norm() const { return as_ref().array_one_norm(); }
  typename vnl_matrix<T>::abs_t array_two_norm() const { return as_ref().array_two_norm(); }
  typename vnl_matrix<T>::abs_t array_inf_norm() const { return as_ref().array_inf_norm(); }
  typename vnl_matrix<T>::abs_t absolute_value_sum() const { return array_one_norm(); }
  typename vnl_matrix<T>::abs_t absolute_value_max() const { return array_inf_norm(); }
  typename vnl_matrix<T>::abs_t operator_one_norm() const { return as_ref().operator_one_norm(); }
  /// Writes one row per line, as vnl_matrix.
  void print(std::ostream& os) const { as_ref().print(os); }
  /// Reads rows() * cols() whitespace-separated values row by row; false if the stream ran out.
  bool read_ascii(std::istream& s) { return as_ref().read_ascii(s); }

  vnl_matrix_fixed<T, num_cols, num_rows> transpose() const {
    vnl_matrix_fixed<T, num_cols, num_rows> result;
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = 0; c < num_cols; ++c) result(c, r) = data_[r][c];
    }
    return result;
  }
  vnl_vector_fixed<T, num_cols> get_row(unsigned r) const { return vnl_vector_fixed<T, num_cols>(data_[r]); }
  vnl_vector_fixed<T, num_rows> get_column(unsigned c) const {
    vnl_vector_fixed<T, num_rows> column;
    for (unsigned r = 0; r < num_rows; ++r) column[r] = data_[r][c];
    return column;
  }
  vnl_matrix_fixed& set_row(unsigned r, const vnl_vector_fixed<T, num_cols>& v) { return set_row(r, v.data_block()); }
  vnl_matrix_fixed& set_row(unsigned r, const vnl_vector<T>& v) {
    assert(v.size() == num_cols);
    return set_row(r, v.data_block());
  }
  vnl_matrix_fixed& set_row(unsigned r, const T* v) {
    for (unsigned c = 0; c < num_cols; ++c) data_[r][c] = v[c];
    return *this;
  }
  vnl_matrix_fixed& set_row(unsigned r, T value) {
    for (unsigned c = 0; c < num_cols; ++c) data_[r][c] = value;
    return *this;
  }
  vnl_matrix_fixed& set_column(unsigned c, const vnl_vector_fixed<T, num_rows>& v) {
    return set_column(c, v.data_block());
  }
  vnl_matrix_fixed& set_column(unsigned c, const vnl_vector<T>& v) {
    assert(v.size() == num_rows);
    return set_column(c, v.data_block());
  }
  vnl_matrix_fixed& set_column(unsigned c, const T* v) {
    for (unsigned r = 0; r < num_rows; ++r) data_[r][c] = v[r];
    return *this;
  }
  vnl_matrix_fixed& set_column(unsigned c, T value) {
    for (unsigned r = 0; r < num_rows; ++r) data_[r][c] = value;
    return *this;
  }
  /// Writes the columns of m from column `starting_column` on.
  vnl_matrix_fixed& set_columns(unsigned starting_column, const vnl_matrix<T>& m) {
    as_ref().non_const().set_columns(starting_column, m);
    return *this;
  }
  vnl_matrix<T> get_rows(const vnl_vector<unsigned int>& i) const { return as_ref().get_rows(i); }
  vnl_matrix<T> get_columns(const vnl_vector<unsigned int>& i) const { return as_ref().get_columns(i); }
  vnl_matrix<T> get_n_rows(unsigned rowstart, unsigned n) const { return as_ref().get_n_rows(rowstart, n); }
  vnl_matrix<T> get_n_columns(unsigned colstart, unsigned n) const { return as_ref().get_n_columns(colstart, n); }
  vnl_vector_fixed<T, num_rows * num_cols> flatten_row_major() const {
    return vnl_vector_fixed<T, num_rows * num_cols>(data_block());
  }
  vnl_vector_fixed<T, num_rows * num_cols> flatten_column_major() const { return transpose().flatten_row_major(); }
  vnl_matrix_fixed<T, num_cols, num_rows> conjugate_transpose() const {
    return vnl_matrix_fixed<T, num_cols, num_rows>(as_ref().conjugate_transpose());
  }
  /// Transposes a square matrix in place.
  vnl_matrix_fixed& inplace_transpose() {
    static_assert(num_rows == num_cols, "in-place transpose of a square matrix");
    return *this = transpose();
  }
  vnl_matrix_fixed& flipud() {
    as_ref().non_const().flipud();
    return *this;
  }
  vnl_matrix_fixed& fliplr() {
    as_ref().non_const().fliplr();
    return *this;
  }
  vnl_matrix_fixed& normalize_rows() {
    as_ref().non_const().normalize_rows();
    return *this;
  }
  vnl_matrix_fixed& normalize_columns() {
    as_ref().non_const().normalize_columns();
    return *this;
  }
  vnl_matrix_fixed& scale_row(unsigned row, T value) {
    for (unsigned c = 0; c < num_cols; ++c) data_[row][c] *= value;
    return *this;
  }
  vnl_matrix_fixed& scale_column(unsigned col, T value) {
    for (unsigned r = 0; r < num_rows; ++r) data_[r][col] *= value;
    return *this;
  }
  void swap(vnl_matrix_fixed& that) {
    for (unsigned i = 0; i < size(); ++i) std::swap(data_block()[i], that.data_block()[i]);
  }
  /// f applied to each element; apply_rowwise / apply_columnwise reduce each row / column.
  vnl_matrix_fixed apply(T (*f)(T)) const { return applied(f); }
  vnl_matrix_fixed apply(T (*f)(const T&)) const { return applied(f); }
  vnl_vector_fixed<T, num_rows> apply_rowwise(T (*f)(const vnl_vector_fixed<T, num_cols>&)) const {
    vnl_vector_fixed<T, num_rows> result;
    for (unsigned r = 0; r < num_rows; ++r) result[r] = f(get_row(r));
    return result;
  }
  vnl_vector_fixed<T, num_cols> apply_columnwise(T (*f)(const vnl_vector_fixed<T, num_rows>&)) const {
    vnl_vector_fixed<T, num_cols> result;
    for (unsigned c = 0; c < num_cols; ++c) result[c] = f(get_column(c));
    return result;
  }
  abs_t rms() const { return as_ref().rms(); }
  T min_value() const { return as_ref().min_value(); }
  T max_value() const { return as_ref().max_value(); }
  unsigned arg_min() const { return unsigned(as_ref().arg_min()); }
  unsigned arg_max() const { return unsigned(as_ref().arg_max()); }
  T mean() const { return as_ref().mean(); }
  bool is_zero(double tol) const { return as_ref().is_zero(tol); }
  bool is_equal(const vnl_matrix_fixed& rhs, double tol) const { return as_ref().is_equal(rhs.as_ref(), tol); }
  bool is_finite() const { return as_ref().is_finite(); }
  bool has_nans() const { return as_ref().has_nans(); }
  void assert_size(unsigned r, unsigned c) const { as_ref().assert_size(r, c); }
  void assert_finite() const { as_ref().assert_finite(); }
  bool operator_eq(const vnl_matrix_fixed& rhs) const { return *this == rhs; }
  bool operator==(const vnl_matrix<T>& that) const { return as_ref() == that; }
  bool operator!=(const vnl_matrix<T>& that) const { return !(as_ref() == that); }

  vnl_matrix_fixed& operator+=(const vnl_matrix_fixed& rhs) {
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = 0; c < num_cols; ++c) data_[r][c] += rhs.data_[r][c];
    }
    return *this;
  }
  vnl_matrix_fixed& operator-=(const vnl_matrix_fixed& rhs) {
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = 0; c < num_cols; ++c) data_[r][c] -= rhs.data_[r][c];
    }
    return *this;
  }
  vnl_matrix_fixed& operator+=(const vnl_matrix<T>& rhs) {
    assert(rhs.rows() == num_rows && rhs.cols() == num_cols);
    for (unsigned i = 0; i < size(); ++i) data_block()[i] += rhs.data_block()[i];
    return *this;
  }
  vnl_matrix_fixed& operator-=(const vnl_matrix<T>& rhs) {
    assert(rhs.rows() == num_rows && rhs.cols() == num_cols);
    for (unsigned i = 0; i < size(); ++i) data_block()[i] -= rhs.data_block()[i];
    return *this;
  }
  /// Right-multiplies by a square matrix in place.
  vnl_matrix_fixed& operator*=(const vnl_matrix_fixed<T, num_cols, num_cols>& s);
  vnl_matrix_fixed& operator+=(T s) {
    for (auto& row : data_) {
      for (T& x : row) x += s;
    }
    return *this;
  }
  vnl_matrix_fixed& operator-=(T s) {
    for (auto& row : data_) {
      for (T& x : row) x -= s;
    }
    return *this;
  }
  vnl_matrix_fixed& operator*=(T s) {
    for (auto& row : data_) {
      for (T& x : row) x *= s;
    }
    return *this;
  }
  vnl_matrix_fixed& operator/=(T s) {
    for (auto& row : data_) {
      for (T& x : row) x /= s;
    }
    return *this;
  }
  vnl_matrix_fixed& fill_diagonal(const T& value) {
    for (unsigned i = 0; i < num_rows && i < num_cols; ++i) data_[i][i] = value;
    return *this;
  }
  vnl_matrix_fixed& set_diagonal(const vnl_vector<T>& v) {
    for (unsigned i = 0; i < v.size(); ++i) data_[i][i] = v[i];
    return *this;
  }
  vnl_vector<T> get_diagonal() const {
    vnl_vector<T> d(num_rows < num_cols ? num_rows : num_cols);
    for (unsigned i = 0; i < d.size(); ++i) d[i] = data_[i][i];
    return d;
  }
  /// Writes `m` into this matrix with its top-left corner at (top, left).
  vnl_matrix_fixed& update(const vnl_matrix<T>& m, unsigned top = 0, unsigned left = 0) {
    for (unsigned r = 0; r < m.rows(); ++r) {
      for (unsigned c = 0; c < m.cols(); ++c) data_[top + r][left + c] = m(r, c);
    }
    return *this;
  }
  vnl_matrix_fixed& update(const vnl_matrix_fixed& m, unsigned top = 0, unsigned left = 0) {
    return update(m.as_ref(), top, left);
  }
  vnl_matrix<T> extract(unsigned rows, unsigned cols, unsigned top = 0, unsigned left = 0) const {
    return as_matrix().extract(rows, cols, top, left);
  }
  /// Fills sub_matrix (already sized) from the block at (top, left).
  void extract(vnl_matrix<T>& sub_matrix, unsigned top = 0, unsigned left = 0) const {
    as_ref().extract(sub_matrix, top, left);
  }
  /// Largest row sum of |a_ij|.
  T operator_inf_norm() const {
    T largest(0);
    for (const auto& row : data_) {
      T total(0);
      for (const T& x : row) total += x < T(0) ? -x : x;
      if (total > largest) largest = total;
    }
    return largest;
  }
  bool is_identity() const { return is_identity(T(0)); }
  bool is_zero() const {
    for (const auto& row : data_) {
      for (const T& x : row) {
        if (!(x == T(0))) return false;
      }
    }
    return true;
  }
  /// -x element by element; unsigned elements give their signed type, as upstream.
  vnl_matrix_fixed<typename vnl_numeric_traits<T>::signed_t, num_rows, num_cols> operator-() const {
    vnl_matrix_fixed<typename vnl_numeric_traits<T>::signed_t, num_rows, num_cols> result;
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = 0; c < num_cols; ++c) result(r, c) = -typename vnl_numeric_traits<T>::signed_t(data_[r][c]);
    }
    return result;
  }

  T frobenius_norm() const {
    using std::sqrt;
    T total(0);
    for (const auto& row : data_) {
      for (const T& x : row) total += x * x;
    }
    return sqrt(total);
  }
  T fro_norm() const { return frobenius_norm(); }
  bool is_identity(const T& tol) const {
    using std::abs;
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = 0; c < num_cols; ++c) {
        if (abs(data_[r][c] - (r == c ? T(1) : T(0))) > tol) return false;
      }
    }
    return true;
  }

  bool operator==(const vnl_matrix_fixed& rhs) const {
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = 0; c < num_cols; ++c) {
        if (data_[r][c] != rhs.data_[r][c]) return false;
      }
    }
    return true;
  }
  bool operator!=(const vnl_matrix_fixed& rhs) const { return !(*this == rhs); }

 private:
  template <class F>
  vnl_matrix_fixed applied(F f) const {
    vnl_matrix_fixed result;
    for (unsigned i = 0; i < size(); ++i) result.data_block()[i] = f(data_block()[i]);
    return result;
  }

  T data_[num_rows][num_cols];
};

template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c>& vnl_matrix_fixed<T, r, c>::operator*=(const vnl_matrix_fixed<T, c, c>& s) {
  return *this = *this * s;
}

template <class T, unsigned r, unsigned c>
void swap(vnl_matrix_fixed<T, r, c>& a, vnl_matrix_fixed<T, r, c>& b) {
  a.swap(b);
}

template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator+(vnl_matrix_fixed<T, r, c> a, const vnl_matrix_fixed<T, r, c>& b) {
  return a += b;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator-(vnl_matrix_fixed<T, r, c> a, const vnl_matrix_fixed<T, r, c>& b) {
  return a -= b;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator+(vnl_matrix_fixed<T, r, c> m, const T& s) {
  return m += s;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator+(const T& s, vnl_matrix_fixed<T, r, c> m) {
  return m += s;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator-(vnl_matrix_fixed<T, r, c> m, const T& s) {
  return m -= s;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator-(const T& s, const vnl_matrix_fixed<T, r, c>& m) {
  return -m + s;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator*(vnl_matrix_fixed<T, r, c> m, const T& s) {
  return m *= s;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator/(vnl_matrix_fixed<T, r, c> m, const T& s) {
  return m /= s;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> element_product(const vnl_matrix_fixed<T, r, c>& a, const vnl_matrix_fixed<T, r, c>& b) {
  vnl_matrix_fixed<T, r, c> result;
  for (unsigned i = 0; i < r; ++i) {
    for (unsigned j = 0; j < c; ++j) result(i, j) = a(i, j) * b(i, j);
  }
  return result;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> element_quotient(const vnl_matrix_fixed<T, r, c>& a, const vnl_matrix_fixed<T, r, c>& b) {
  vnl_matrix_fixed<T, r, c> result;
  for (unsigned i = 0; i < r; ++i) {
    for (unsigned j = 0; j < c; ++j) result(i, j) = a(i, j) / b(i, j);
  }
  return result;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator*(const T& s, vnl_matrix_fixed<T, r, c> m) {
  return m *= s;
}

template <class T, unsigned r, unsigned k, unsigned c>
vnl_matrix_fixed<T, r, c> operator*(const vnl_matrix_fixed<T, r, k>& a, const vnl_matrix_fixed<T, k, c>& b) {
  vnl_matrix_fixed<T, r, c> result;
  for (unsigned i = 0; i < r; ++i) {
    for (unsigned j = 0; j < c; ++j) {
      T total(0);
      for (unsigned l = 0; l < k; ++l) total += a(i, l) * b(l, j);
      result(i, j) = total;
    }
  }
  return result;
}

template <class T, unsigned r, unsigned c>
vnl_vector_fixed<T, r> operator*(const vnl_matrix_fixed<T, r, c>& m, const vnl_vector_fixed<T, c>& v) {
  vnl_vector_fixed<T, r> result;
  for (unsigned i = 0; i < r; ++i) {
    T total(0);
    for (unsigned j = 0; j < c; ++j) total += m(i, j) * v[j];
    result[i] = total;
  }
  return result;
}

template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> outer_product(const vnl_vector_fixed<T, r>& a, const vnl_vector_fixed<T, c>& b) {
  vnl_matrix_fixed<T, r, c> result;
  for (unsigned i = 0; i < r; ++i) {
    for (unsigned j = 0; j < c; ++j) result(i, j) = a[i] * b[j];
  }
  return result;
}

using vnl_double_3x3 = vnl_matrix_fixed<double, 3, 3>;

template <class T, unsigned r, unsigned c>
std::ostream& operator<<(std::ostream& os, const vnl_matrix_fixed<T, r, c>& m) {
  m.print(os);
  return os;
}
template <class T, unsigned r, unsigned c>
std::istream& operator>>(std::istream& is, vnl_matrix_fixed<T, r, c>& m) {
  m.read_ascii(is);
  return is;
}

/// Sums and differences of a fixed and a dense matrix, as upstream's (a dense vnl_matrix result).
template <class T, unsigned r, unsigned c>
vnl_matrix<T> operator+(const vnl_matrix_fixed<T, r, c>& a, const vnl_matrix<T>& b) {
  return a.as_ref() + b;
}
template <class T, unsigned r, unsigned c>
vnl_matrix<T> operator+(const vnl_matrix<T>& a, const vnl_matrix_fixed<T, r, c>& b) {
  return a + b.as_ref();
}
template <class T, unsigned r, unsigned c>
vnl_matrix<T> operator-(const vnl_matrix_fixed<T, r, c>& a, const vnl_matrix<T>& b) {
  return a.as_ref() - b;
}
template <class T, unsigned r, unsigned c>
vnl_matrix<T> operator-(const vnl_matrix<T>& a, const vnl_matrix_fixed<T, r, c>& b) {
  return a - b.as_ref();
}

/// Products of a fixed and a dense matrix, as upstream's (a dense vnl_matrix result).
template <class T, unsigned r, unsigned c>
vnl_matrix<T> operator*(const vnl_matrix_fixed<T, r, c>& a, const vnl_matrix<T>& b) {
  return a.as_ref() * b;
}
template <class T, unsigned r, unsigned c>
vnl_matrix<T> operator*(const vnl_matrix<T>& a, const vnl_matrix_fixed<T, r, c>& b) {
  return a * b.as_ref();
}

}  // inline namespace edgetrack_ports
