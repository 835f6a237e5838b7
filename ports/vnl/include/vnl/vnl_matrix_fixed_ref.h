// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matrix_fixed_ref.h: views of a num_rows x num_cols row-major
/// block held elsewhere, with vnl_matrix_fixed's interface; the _const view reads, the other
/// also writes through. Header-only.
#pragma once

#ifdef vnl_matrix_fixed_ref_h_
#error "edgetrack's drop-in vnl/vnl_matrix_fixed_ref.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_c_vector.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_matrix_ref.h"
#include "vnl/vnl_vector_fixed.h"
#include "vnl/vnl_vector_fixed_ref.h"

inline namespace edgetrack_ports {

template <class T, unsigned int num_rows, unsigned int num_cols>
class vnl_matrix_fixed_ref_const {
 public:
  using abs_t = typename vnl_numeric_traits<T>::abs_t;
  using fixed = vnl_matrix_fixed<T, num_rows, num_cols>;

  vnl_matrix_fixed_ref_const(const fixed& rhs) : data_(const_cast<T*>(rhs.data_block())) {}
  explicit vnl_matrix_fixed_ref_const(const T* dataptr) : data_(const_cast<T*>(dataptr)) {}

  const T* data_block() const { return data_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size(); }
  static constexpr unsigned rows() { return num_rows; }
  static constexpr unsigned cols() { return num_cols; }
  static constexpr unsigned columns() { return num_cols; }
  static constexpr unsigned size() { return num_rows * num_cols; }
  const T& operator()(unsigned r, unsigned c) const { return data_[r * num_cols + c]; }
  const T* operator[](unsigned r) const { return data_ + r * num_cols; }
  T get(unsigned r, unsigned c) const { return (*this)(r, c); }
  vnl_vector_fixed<T, num_cols> get_row(unsigned r) const { return vnl_vector_fixed<T, num_cols>((*this)[r]); }
  vnl_vector_fixed<T, num_rows> get_column(unsigned c) const {
    vnl_vector_fixed<T, num_rows> v;
    for (unsigned r = 0; r < num_rows; ++r) v[r] = (*this)(r, c);
    return v;
  }
  vnl_vector<T> get_diagonal() const { return as_matrix().get_diagonal(); }
  vnl_matrix<T> as_matrix() const { return vnl_matrix<T>(data_, num_rows, num_cols); }
  const vnl_matrix_ref<T> as_ref() const { return vnl_matrix_ref<T>(num_rows, num_cols, data_); }
  fixed as_fixed() const { return fixed(data_); }
  vnl_matrix_fixed<T, num_cols, num_rows> transpose() const { return as_fixed().transpose(); }
  vnl_matrix<T> extract(unsigned r, unsigned c, unsigned top = 0, unsigned left = 0) const {
    return as_matrix().extract(r, c, top, left);
  }
  abs_t frobenius_norm() const { return vnl_c_vector<T>::two_norm(data_, size()); }
  abs_t fro_norm() const { return frobenius_norm(); }
  abs_t array_one_norm() const { return vnl_c_vector<T>::one_norm(data_, size()); }
  abs_t array_inf_norm() const { return vnl_c_vector<T>::inf_norm(data_, size()); }
  abs_t absolute_value_max() const { return array_inf_norm(); }
  T min_value() const { return vnl_c_vector<T>::min_value(data_, size()); }
  T max_value() const { return vnl_c_vector<T>::max_value(data_, size()); }
  T mean() const { return vnl_c_vector<T>::mean(data_, size()); }
  bool is_identity() const { return as_matrix().is_identity(); }
  bool is_zero() const { return as_matrix().is_zero(); }
  bool operator==(const vnl_matrix_fixed_ref_const& that) const {
    for (unsigned i = 0; i < size(); ++i) {
      if (!(data_[i] == that.data_[i])) return false;
    }
    return true;
  }
  bool operator!=(const vnl_matrix_fixed_ref_const& that) const { return !(*this == that); }

 protected:
  T* data_;
};

template <class T, unsigned int num_rows, unsigned int num_cols>
class vnl_matrix_fixed_ref : public vnl_matrix_fixed_ref_const<T, num_rows, num_cols> {
  using Base = vnl_matrix_fixed_ref_const<T, num_rows, num_cols>;

 public:
  using fixed = vnl_matrix_fixed<T, num_rows, num_cols>;

  vnl_matrix_fixed_ref(fixed& rhs) : Base(rhs.data_block()) {}
  explicit vnl_matrix_fixed_ref(T* dataptr) : Base(dataptr) {}
  /// Copies values into the viewed block (never rebinds the view).
  const vnl_matrix_fixed_ref& operator=(const fixed& rhs) const { return copy_in(rhs.data_block()); }
  const vnl_matrix_fixed_ref& operator=(const Base& rhs) const { return copy_in(rhs.data_block()); }

  T* data_block() const { return this->data_; }
  T* begin() const { return this->data_; }
  T* end() const { return this->data_ + Base::size(); }
  T& operator()(unsigned r, unsigned c) const { return this->data_[r * num_cols + c]; }
  T* operator[](unsigned r) const { return this->data_ + r * num_cols; }
  void put(unsigned r, unsigned c, const T& v) const { (*this)(r, c) = v; }
  vnl_matrix_ref<T> as_ref() const { return vnl_matrix_ref<T>(num_rows, num_cols, this->data_); }

  const vnl_matrix_fixed_ref& fill(const T& v) const {
    vnl_c_vector<T>::fill(this->data_, Base::size(), v);
    return *this;
  }
  const vnl_matrix_fixed_ref& fill_diagonal(const T& v) const {
    for (unsigned i = 0; i < num_rows && i < num_cols; ++i) (*this)(i, i) = v;
    return *this;
  }
  const vnl_matrix_fixed_ref& set_diagonal(const vnl_vector<T>& v) const {
    for (unsigned i = 0; i < v.size(); ++i) (*this)(i, i) = v[i];
    return *this;
  }
  const vnl_matrix_fixed_ref& set_identity() const {
    fill(T(0));
    return fill_diagonal(T(1));
  }
  const vnl_matrix_fixed_ref& copy_in(const T* p) const {
    vnl_c_vector<T>::copy(p, this->data_, Base::size());
    return *this;
  }
  const vnl_matrix_fixed_ref& set_row(unsigned r, const vnl_vector_fixed<T, num_cols>& v) const {
    for (unsigned c = 0; c < num_cols; ++c) (*this)(r, c) = v[c];
    return *this;
  }
  const vnl_matrix_fixed_ref& set_column(unsigned c, const vnl_vector_fixed<T, num_rows>& v) const {
    for (unsigned r = 0; r < num_rows; ++r) (*this)(r, c) = v[r];
    return *this;
  }
  const vnl_matrix_fixed_ref& update(const vnl_matrix<T>& m, unsigned top = 0, unsigned left = 0) const {
    for (unsigned r = 0; r < m.rows(); ++r) {
      for (unsigned c = 0; c < m.cols(); ++c) (*this)(top + r, left + c) = m(r, c);
    }
    return *this;
  }
  const vnl_matrix_fixed_ref& operator+=(const T& s) const {
    for (unsigned i = 0; i < Base::size(); ++i) this->data_[i] += s;
    return *this;
  }
  const vnl_matrix_fixed_ref& operator-=(const T& s) const {
    for (unsigned i = 0; i < Base::size(); ++i) this->data_[i] -= s;
    return *this;
  }
  const vnl_matrix_fixed_ref& operator*=(const T& s) const {
    for (unsigned i = 0; i < Base::size(); ++i) this->data_[i] *= s;
    return *this;
  }
  const vnl_matrix_fixed_ref& operator/=(const T& s) const {
    for (unsigned i = 0; i < Base::size(); ++i) this->data_[i] /= s;
    return *this;
  }
  const vnl_matrix_fixed_ref& operator+=(const Base& m) const {
    for (unsigned i = 0; i < Base::size(); ++i) this->data_[i] += m.data_block()[i];
    return *this;
  }
  const vnl_matrix_fixed_ref& operator-=(const Base& m) const {
    for (unsigned i = 0; i < Base::size(); ++i) this->data_[i] -= m.data_block()[i];
    return *this;
  }
  /// Transposes in place (square only).
  const vnl_matrix_fixed_ref& inplace_transpose() const {
    static_assert(num_rows == num_cols, "inplace_transpose of a fixed view needs a square block");
    for (unsigned r = 0; r < num_rows; ++r) {
      for (unsigned c = r + 1; c < num_cols; ++c) {
        const T t = (*this)(r, c);
        (*this)(r, c) = (*this)(c, r);
        (*this)(c, r) = t;
      }
    }
    return *this;
  }
  const vnl_matrix_fixed_ref& flipud() const {
    as_ref().flipud();
    return *this;
  }
  const vnl_matrix_fixed_ref& fliplr() const {
    as_ref().fliplr();
    return *this;
  }
  const vnl_matrix_fixed_ref& normalize_rows() const {
    as_ref().normalize_rows();
    return *this;
  }
  const vnl_matrix_fixed_ref& normalize_columns() const {
    as_ref().normalize_columns();
    return *this;
  }
  const vnl_matrix_fixed_ref& scale_row(unsigned r, T v) const {
    for (unsigned c = 0; c < num_cols; ++c) (*this)(r, c) *= v;
    return *this;
  }
  const vnl_matrix_fixed_ref& scale_column(unsigned c, T v) const {
    for (unsigned r = 0; r < num_rows; ++r) (*this)(r, c) *= v;
    return *this;
  }
};

template <class T, unsigned r, unsigned k, unsigned c>
vnl_matrix_fixed<T, r, c> operator*(const vnl_matrix_fixed_ref_const<T, r, k>& a,
                                    const vnl_matrix_fixed_ref_const<T, k, c>& b) {
  return a.as_fixed() * b.as_fixed();
}
template <class T, unsigned r, unsigned c>
vnl_vector_fixed<T, r> operator*(const vnl_matrix_fixed_ref_const<T, r, c>& a,
                                 const vnl_vector_fixed_ref_const<T, c>& v) {
  return a.as_fixed() * v.as_fixed();
}

/// Sums and differences of two views, into a fixed matrix, as upstream's.
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator+(const vnl_matrix_fixed_ref_const<T, r, c>& a,
                                    const vnl_matrix_fixed_ref_const<T, r, c>& b) {
  return a.as_fixed() + b.as_fixed();
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<T, r, c> operator-(const vnl_matrix_fixed_ref_const<T, r, c>& a,
                                    const vnl_matrix_fixed_ref_const<T, r, c>& b) {
  return a.as_fixed() - b.as_fixed();
}

}  // inline namespace edgetrack_ports
