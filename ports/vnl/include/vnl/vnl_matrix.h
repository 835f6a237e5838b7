// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matrix.h: a heap-allocated, row-major matrix of T with vnl's
/// names (rows, cols, set_size, transpose, get_row, set_column, extract, update...). Like
/// upstream it may view a block it does not own (vnl_matrix_ref). Declarations only;
/// vnl_matrix.hxx defines them, instances/ instantiates them per scalar.
#pragma once

#ifdef vnl_matrix_h_
#error "edgetrack's drop-in vnl/vnl_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>
#include <initializer_list>
#include <iosfwd>
#include <type_traits>

#include "vnl/vnl_numeric_traits.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_matrix_ref;

/// Tags of upstream's vnl_matrix(r, c, op, ...) constructors.
enum vnl_matrix_type { vnl_matrix_null, vnl_matrix_identity };

template <class T>
class vnl_matrix {
 public:
  using element_type = T;
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;
  using abs_t = typename vnl_numeric_traits<T>::abs_t;

  vnl_matrix() = default;
  /// rows x cols zeros (upstream leaves them uninitialised).
  vnl_matrix(std::size_t rows, std::size_t cols);
  vnl_matrix(std::size_t rows, std::size_t cols, const T& value);
  /// rows x cols with the first n values (row-major) from `values`, the rest zero.
  vnl_matrix(std::size_t rows, std::size_t cols, std::size_t n, const T values[]);
  /// vnl_matrix_null gives zeros, vnl_matrix_identity the identity.
  vnl_matrix(std::size_t rows, std::size_t cols, vnl_matrix_type type);
  /// Copies rows*cols elements from row-major `data`.
  vnl_matrix(const T* data, std::size_t rows, std::size_t cols);
  /// Rows given as nested lists, as vnl_matrix<double> m{{1, 2}, {3, 4}}.
  vnl_matrix(std::initializer_list<std::initializer_list<T>> rows);
  /// Views the row-major block at `data`; frees it with delete[] only if `manage_own_memory`.
  vnl_matrix(std::size_t rows, std::size_t cols, T* data, bool manage_own_memory);
  vnl_matrix(const vnl_matrix& that);
  vnl_matrix(vnl_matrix&& that) noexcept;
  ~vnl_matrix();

  vnl_matrix& operator=(const vnl_matrix& rhs);
  vnl_matrix& operator=(vnl_matrix&& rhs);
  vnl_matrix& operator=(const T& v) { return fill(v); }

  std::size_t rows() const { return num_rows_; }
  std::size_t cols() const { return num_cols_; }
  std::size_t columns() const { return num_cols_; }
  std::size_t size() const { return num_rows_ * num_cols_; }
  bool empty() const { return size() == 0; }
  /// Resizes; the contents are zero afterwards. Views cannot resize.
  bool set_size(std::size_t rows, std::size_t cols);
  void clear();

  T& operator()(std::size_t r, std::size_t c) { return data_[r * num_cols_ + c]; }
  const T& operator()(std::size_t r, std::size_t c) const { return data_[r * num_cols_ + c]; }
  /// Row r, as upstream's m[r][c].
  T* operator[](std::size_t r) { return data_ + r * num_cols_; }
  const T* operator[](std::size_t r) const { return data_ + r * num_cols_; }
  T get(std::size_t r, std::size_t c) const { return (*this)(r, c); }
  void put(std::size_t r, std::size_t c, const T& v) { (*this)(r, c) = v; }

  T* data_block() { return data_; }
  const T* data_block() const { return data_; }
  /// Row pointers, as upstream's T**.
  T* const* data_array() { return row_pointers_; }
  T const* const* data_array() const { return row_pointers_; }
  iterator begin() { return data_; }
  iterator end() { return data_ + size(); }
  const_iterator begin() const { return data_; }
  const_iterator end() const { return data_ + size(); }
  vnl_matrix_ref<T> as_ref();
  const vnl_matrix_ref<T> as_ref() const;

  vnl_matrix& fill(const T& value);
  vnl_matrix& fill_diagonal(const T& value);
  /// Puts v on the main diagonal (v.size() <= min(rows, cols)).
  vnl_matrix& set_diagonal(const vnl_vector<T>& v);
  /// Makes the matrix the identity (any shape: ones on the main diagonal).
  vnl_matrix& set_identity();
  vnl_matrix& copy_in(const T* data);
  vnl_matrix& set(const T* data) { return copy_in(data); }
  void copy_out(T* data) const;

  /// The scalar forms take T by value, as upstream, so m /= m[0][0] divides by the old value.
  vnl_matrix& operator+=(T value);
  vnl_matrix& operator-=(T value);
  vnl_matrix& operator*=(T value);
  vnl_matrix& operator/=(T value);
  vnl_matrix& operator+=(const vnl_matrix& rhs);
  vnl_matrix& operator-=(const vnl_matrix& rhs);
  vnl_matrix& operator*=(const vnl_matrix& rhs) { return *this = *this * rhs; }

  /// -x element by element; unsigned elements give their signed type, as upstream.
  vnl_matrix<typename vnl_numeric_traits<T>::signed_t> operator-() const;
  vnl_matrix operator+(const T& v) const;
  vnl_matrix operator-(const T& v) const;
  vnl_matrix operator*(const T& v) const;
  vnl_matrix operator/(const T& v) const;
  vnl_matrix operator+(const vnl_matrix& rhs) const;
  vnl_matrix operator-(const vnl_matrix& rhs) const;
  vnl_matrix operator*(const vnl_matrix& rhs) const;

  /// f applied to each element; apply_rowwise / apply_columnwise reduce each row / column.
  vnl_matrix apply(T (*f)(T)) const;
  vnl_matrix apply(T (*f)(const T&)) const;
  vnl_vector<T> apply_rowwise(T (*f)(const vnl_vector<T>&)) const;
  vnl_vector<T> apply_columnwise(T (*f)(const vnl_vector<T>&)) const;

  vnl_matrix transpose() const;
  vnl_matrix conjugate_transpose() const;
  /// Transposes in place; a non-square matrix swaps its dimensions.
  vnl_matrix& inplace_transpose();

  /// Writes `m` into this matrix with its top-left corner at (top, left).
  vnl_matrix& update(const vnl_matrix& m, std::size_t top = 0, std::size_t left = 0);
  vnl_matrix& set_column(std::size_t c, const T* v);
  vnl_matrix& set_column(std::size_t c, T value);
  vnl_matrix& set_column(std::size_t c, const vnl_vector<T>& v);
  /// Writes the columns of m from column `starting_column` on.
  vnl_matrix& set_columns(std::size_t starting_column, const vnl_matrix& m);
  vnl_matrix& set_row(std::size_t r, const T* v);
  vnl_matrix& set_row(std::size_t r, T value);
  vnl_matrix& set_row(std::size_t r, const vnl_vector<T>& v);
  /// The rows x cols block whose top-left corner is (top, left).
  vnl_matrix extract(std::size_t rows, std::size_t cols, std::size_t top = 0, std::size_t left = 0) const;
  /// Fills sub_matrix (already sized) from the block at (top, left).
  void extract(vnl_matrix& sub_matrix, std::size_t top = 0, std::size_t left = 0) const;
  vnl_vector<T> get_row(std::size_t r) const;
  vnl_vector<T> get_column(std::size_t c) const;
  vnl_matrix get_rows(const vnl_vector<unsigned int>& i) const;
  vnl_matrix get_columns(const vnl_vector<unsigned int>& i) const;
  vnl_matrix get_n_rows(std::size_t rowstart, std::size_t n) const;
  vnl_matrix get_n_columns(std::size_t colstart, std::size_t n) const;
  vnl_vector<T> get_diagonal() const;
  vnl_vector<T> flatten_row_major() const;
  vnl_vector<T> flatten_column_major() const;

  /// Reverses the order of the rows (flipud) or of the columns (fliplr).
  vnl_matrix& flipud();
  vnl_matrix& fliplr();
  /// Scales each row (column) to unit two-norm; zero rows stay zero.
  vnl_matrix& normalize_rows();
  vnl_matrix& normalize_columns();
  vnl_matrix& scale_row(std::size_t row, T value);
  vnl_matrix& scale_column(std::size_t col, T value);
  void swap(vnl_matrix& that) noexcept;

  /// Norms of the elements taken as one long vector.
  abs_t array_one_norm() const;
  abs_t array_two_norm() const;
  abs_t array_inf_norm() const;
  abs_t absolute_value_sum() const { return array_one_norm(); }
  abs_t absolute_value_max() const { return array_inf_norm(); }
  /// Largest column sum (one) or row sum (inf) of |a_ij|.
  abs_t operator_one_norm() const;
  abs_t operator_inf_norm() const;
  abs_t frobenius_norm() const { return array_two_norm(); }
  abs_t fro_norm() const { return array_two_norm(); }
  abs_t rms() const;
  T min_value() const;
  T max_value() const;
  std::size_t arg_min() const;
  std::size_t arg_max() const;
  T mean() const;

  bool is_identity() const;
  bool is_identity(double tol) const;
  bool is_zero() const;
  bool is_zero(double tol) const;
  bool is_equal(const vnl_matrix& rhs, double tol) const;
  /// The tolerance forms for a non-double scalar, compared in that scalar.
  template <class U = T, std::enable_if_t<!std::is_same_v<typename vnl_numeric_traits<U>::abs_t, double>, int> = 0>
  bool is_identity(const abs_t& tol) const {
    for (std::size_t r = 0; r < num_rows_; ++r) {
      for (std::size_t c = 0; c < num_cols_; ++c) {
        const T expected = r == c ? T(1) : T(0);
        const T d = (*this)(r, c) - expected;
        if (abs_t(d < T(0) ? -d : d) > tol) return false;
      }
    }
    return true;
  }
  bool is_finite() const;
  bool has_nans() const;
  void assert_size(std::size_t r, std::size_t c) const;
  void assert_finite() const;

  bool operator_eq(const vnl_matrix& rhs) const;
  bool operator==(const vnl_matrix& that) const { return operator_eq(that); }
  bool operator!=(const vnl_matrix& that) const { return !operator_eq(that); }

  /// Reads rows()*cols() values; an empty matrix reads rows of values up to the end.
  bool read_ascii(std::istream& s);
  static vnl_matrix read(std::istream& s);
  void print(std::ostream& os) const;

 private:
  void destroy();
  void make_row_pointers();

  T* data_ = nullptr;
  T** row_pointers_ = nullptr;
  std::size_t num_rows_ = 0;
  std::size_t num_cols_ = 0;
  bool own_memory_ = true;
};

template <class T>
vnl_matrix<T> operator+(const T& s, const vnl_matrix<T>& m) {
  return m + s;
}
template <class T>
vnl_matrix<T> operator-(const T& s, const vnl_matrix<T>& m) {
  return -(m - s);
}
template <class T>
vnl_matrix<T> operator*(const T& s, const vnl_matrix<T>& m) {
  return m * s;
}

/// Matrix-vector product m * v.
template <class T>
vnl_vector<T> operator*(const vnl_matrix<T>& m, const vnl_vector<T>& v);
/// Outer product a * b^T.
template <class T>
vnl_matrix<T> outer_product(const vnl_vector<T>& a, const vnl_vector<T>& b);
template <class T>
vnl_matrix<T> element_product(const vnl_matrix<T>& a, const vnl_matrix<T>& b);
template <class T>
vnl_matrix<T> element_quotient(const vnl_matrix<T>& a, const vnl_matrix<T>& b);
/// sum_ij a_ij * b_ij.
template <class T>
T dot_product(const vnl_matrix<T>& a, const vnl_matrix<T>& b);
/// sum_ij a_ij * conj(b_ij).
template <class T>
T inner_product(const vnl_matrix<T>& a, const vnl_matrix<T>& b);
/// The cosine of the angle between a and b taken as vectors.
template <class T>
T cos_angle(const vnl_matrix<T>& a, const vnl_matrix<T>& b);

template <class T>
void swap(vnl_matrix<T>& a, vnl_matrix<T>& b) noexcept {
  a.swap(b);
}

/// Prints one row per line, elements separated by spaces.
template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_matrix<T>& m);
template <class T>
std::istream& operator>>(std::istream& s, vnl_matrix<T>& m);

}  // inline namespace edgetrack_ports
