// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_vector_fixed_ref.h: views of n contiguous T's held elsewhere,
/// with vnl_vector_fixed's interface. vnl_vector_fixed_ref_const reads; vnl_vector_fixed_ref
/// also writes through to the viewed memory. Header-only.
#pragma once

#ifdef vnl_vector_fixed_ref_h_
#error "edgetrack's drop-in vnl/vnl_vector_fixed_ref.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>

#include "vnl/vnl_c_vector.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"
#include "vnl/vnl_vector_ref.h"

inline namespace edgetrack_ports {

template <class T, unsigned int n>
class vnl_vector_fixed_ref_const {
 public:
  using abs_t = typename vnl_numeric_traits<T>::abs_t;
  using const_iterator = const T*;

  vnl_vector_fixed_ref_const(const vnl_vector_fixed<T, n>& rhs) : data_(const_cast<T*>(rhs.data_block())) {}
  explicit vnl_vector_fixed_ref_const(const T* dataptr) : data_(const_cast<T*>(dataptr)) {}

  const T* data_block() const { return data_; }
  static constexpr unsigned size() { return n; }
  T get(unsigned i) const { return data_[i]; }
  void copy_out(T* ptr) const { vnl_c_vector<T>::copy(data_, ptr, n); }
  const T& operator()(unsigned i) const { return data_[i]; }
  const T& operator[](unsigned i) const { return data_[i]; }
  const_iterator begin() const { return data_; }
  const_iterator end() const { return data_ + n; }
  const vnl_vector_ref<T> as_ref() const { return vnl_vector_ref<T>(n, data_); }
  vnl_vector<T> as_vector() const { return vnl_vector<T>(data_, n); }
  operator vnl_vector<T>() const { return as_vector(); }
  /// A by-value copy.
  vnl_vector_fixed<T, n> as_fixed() const { return vnl_vector_fixed<T, n>(data_); }

  vnl_vector_fixed<T, n> apply(T (*f)(T)) const {
    vnl_vector_fixed<T, n> result;
    for (unsigned i = 0; i < n; ++i) result[i] = f(data_[i]);
    return result;
  }
  vnl_vector_fixed<T, n> operator-() const { return -as_fixed(); }
  vnl_vector<T> extract(unsigned len, unsigned start = 0) const { return as_vector().extract(len, start); }

  abs_t squared_magnitude() const { return vnl_c_vector<T>::two_nrm2(data_, n); }
  abs_t magnitude() const { return two_norm(); }
  abs_t one_norm() const { return vnl_c_vector<T>::one_norm(data_, n); }
  abs_t two_norm() const { return vnl_c_vector<T>::two_norm(data_, n); }
  abs_t inf_norm() const { return vnl_c_vector<T>::inf_norm(data_, n); }
  abs_t rms() const { return vnl_c_vector<T>::rms_norm(data_, n); }
  T min_value() const { return vnl_c_vector<T>::min_value(data_, n); }
  T max_value() const { return vnl_c_vector<T>::max_value(data_, n); }
  unsigned arg_min() const { return vnl_c_vector<T>::arg_min(data_, n); }
  unsigned arg_max() const { return vnl_c_vector<T>::arg_max(data_, n); }
  T mean() const { return vnl_c_vector<T>::mean(data_, n); }
  T sum() const { return vnl_c_vector<T>::sum(data_, n); }
  bool is_zero() const {
    for (unsigned i = 0; i < n; ++i) {
      if (!(data_[i] == T(0))) return false;
    }
    return true;
  }
  bool operator==(const vnl_vector_fixed_ref_const& that) const {
    for (unsigned i = 0; i < n; ++i) {
      if (!(data_[i] == that.data_[i])) return false;
    }
    return true;
  }
  bool operator!=(const vnl_vector_fixed_ref_const& that) const { return !(*this == that); }

 protected:
  T* data_;
};

template <class T, unsigned int n>
class vnl_vector_fixed_ref : public vnl_vector_fixed_ref_const<T, n> {
  using Base = vnl_vector_fixed_ref_const<T, n>;

 public:
  using iterator = T*;

  vnl_vector_fixed_ref(vnl_vector_fixed<T, n>& rhs) : Base(rhs.data_block()) {}
  explicit vnl_vector_fixed_ref(T* dataptr) : Base(dataptr) {}
  /// Copies values into the viewed memory (never rebinds the view).
  const vnl_vector_fixed_ref& operator=(const vnl_vector_fixed<T, n>& rhs) const {
    vnl_c_vector<T>::copy(rhs.data_block(), this->data_, n);
    return *this;
  }
  const vnl_vector_fixed_ref& operator=(const vnl_vector_fixed_ref_const<T, n>& rhs) const {
    vnl_c_vector<T>::copy(rhs.data_block(), this->data_, n);
    return *this;
  }

  T* data_block() const { return this->data_; }
  void put(unsigned i, const T& v) const { this->data_[i] = v; }
  T& operator()(unsigned i) const { return this->data_[i]; }
  T& operator[](unsigned i) const { return this->data_[i]; }
  iterator begin() const { return this->data_; }
  iterator end() const { return this->data_ + n; }
  vnl_vector_ref<T> as_ref() const { return vnl_vector_ref<T>(n, this->data_); }

  const vnl_vector_fixed_ref& fill(const T& v) const {
    vnl_c_vector<T>::fill(this->data_, n, v);
    return *this;
  }
  const vnl_vector_fixed_ref& copy_in(const T* ptr) const {
    vnl_c_vector<T>::copy(ptr, this->data_, n);
    return *this;
  }
  const vnl_vector_fixed_ref& operator+=(const T& s) const {
    for (unsigned i = 0; i < n; ++i) this->data_[i] += s;
    return *this;
  }
  const vnl_vector_fixed_ref& operator-=(const T& s) const {
    for (unsigned i = 0; i < n; ++i) this->data_[i] -= s;
    return *this;
  }
  const vnl_vector_fixed_ref& operator*=(const T& s) const {
    for (unsigned i = 0; i < n; ++i) this->data_[i] *= s;
    return *this;
  }
  const vnl_vector_fixed_ref& operator/=(const T& s) const {
    for (unsigned i = 0; i < n; ++i) this->data_[i] /= s;
    return *this;
  }
  const vnl_vector_fixed_ref& operator+=(const vnl_vector_fixed_ref_const<T, n>& v) const {
    for (unsigned i = 0; i < n; ++i) this->data_[i] += v[i];
    return *this;
  }
  const vnl_vector_fixed_ref& operator-=(const vnl_vector_fixed_ref_const<T, n>& v) const {
    for (unsigned i = 0; i < n; ++i) this->data_[i] -= v[i];
    return *this;
  }
  const vnl_vector_fixed_ref& update(const vnl_vector<T>& v, unsigned start = 0) const {
    for (std::size_t i = 0; i < v.size(); ++i) this->data_[start + i] = v[i];
    return *this;
  }
  const vnl_vector_fixed_ref& normalize() const {
    vnl_c_vector<T>::normalize(this->data_, n);
    return *this;
  }
  const vnl_vector_fixed_ref& flip() const {
    vnl_c_vector<T>::reverse(this->data_, n);
    return *this;
  }
};

template <class T, unsigned n>
vnl_vector_fixed<T, n> operator+(const vnl_vector_fixed_ref_const<T, n>& a, const vnl_vector_fixed_ref_const<T, n>& b) {
  return a.as_fixed() + b.as_fixed();
}
template <class T, unsigned n>
vnl_vector_fixed<T, n> operator-(const vnl_vector_fixed_ref_const<T, n>& a, const vnl_vector_fixed_ref_const<T, n>& b) {
  return a.as_fixed() - b.as_fixed();
}
template <class T, unsigned n>
T dot_product(const vnl_vector_fixed_ref_const<T, n>& a, const vnl_vector_fixed_ref_const<T, n>& b) {
  return vnl_c_vector<T>::dot_product(a.data_block(), b.data_block(), n);
}

}  // inline namespace edgetrack_ports
