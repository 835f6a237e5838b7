// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_vector.h (upstream: core/vnl/vnl_vector.hxx). Include it only to
/// instantiate vnl_vector for a scalar that the library does not instantiate.
#pragma once

#include <cassert>
#include <cmath>
#include <ostream>

#include "vnl/vnl_vector.h"

template <class T>
vnl_vector<T>::vnl_vector(std::size_t n) : data_(n, T(0)) {}

template <class T>
vnl_vector<T>::vnl_vector(std::size_t n, const T& value) : data_(n, value) {}

template <class T>
vnl_vector<T>::vnl_vector(const T* data, std::size_t n) : data_(data, data + n) {}

template <class T>
bool vnl_vector<T>::set_size(std::size_t n) {
  data_.assign(n, T(0));
  return true;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::fill(const T& value) {
  for (T& x : data_) x = value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::copy_in(const T* data) {
  for (std::size_t i = 0; i < data_.size(); ++i) data_[i] = data[i];
  return *this;
}

template <class T>
void vnl_vector<T>::copy_out(T* data) const {
  for (std::size_t i = 0; i < data_.size(); ++i) data[i] = data_[i];
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator+=(const vnl_vector& rhs) {
  assert(rhs.size() == size());
  for (std::size_t i = 0; i < data_.size(); ++i) data_[i] += rhs.data_[i];
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator-=(const vnl_vector& rhs) {
  assert(rhs.size() == size());
  for (std::size_t i = 0; i < data_.size(); ++i) data_[i] -= rhs.data_[i];
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator+=(const T& value) {
  for (T& x : data_) x += value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator-=(const T& value) {
  for (T& x : data_) x -= value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator*=(const T& value) {
  for (T& x : data_) x *= value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator/=(const T& value) {
  for (T& x : data_) x /= value;
  return *this;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator-() const {
  vnl_vector result(size());
  for (std::size_t i = 0; i < data_.size(); ++i) result.data_[i] = -data_[i];
  return result;
}

template <class T>
vnl_vector<T> vnl_vector<T>::extract(std::size_t n, std::size_t start) const {
  assert(start + n <= size());
  return vnl_vector(data_.data() + start, n);
}

template <class T>
vnl_vector<T>& vnl_vector<T>::update(const vnl_vector& v, std::size_t start) {
  assert(start + v.size() <= size());
  for (std::size_t i = 0; i < v.size(); ++i) data_[start + i] = v.data_[i];
  return *this;
}

template <class T>
T vnl_vector<T>::sum() const {
  T total(0);
  for (const T& x : data_) total += x;
  return total;
}

template <class T>
T vnl_vector<T>::mean() const {
  return data_.empty() ? T(0) : sum() / T(static_cast<int>(data_.size()));
}

template <class T>
T vnl_vector<T>::squared_magnitude() const {
  T total(0);
  for (const T& x : data_) total += x * x;
  return total;
}

template <class T>
T vnl_vector<T>::one_norm() const {
  using std::abs;
  T total(0);
  for (const T& x : data_) total += abs(x);
  return total;
}

template <class T>
T vnl_vector<T>::two_norm() const {
  using std::sqrt;
  return sqrt(squared_magnitude());
}

template <class T>
T vnl_vector<T>::inf_norm() const {
  using std::abs;
  T largest(0);
  for (const T& x : data_) {
    const T a = abs(x);
    if (a > largest) largest = a;
  }
  return largest;
}

template <class T>
T vnl_vector<T>::rms() const {
  using std::sqrt;
  return data_.empty() ? T(0) : sqrt(squared_magnitude() / T(static_cast<int>(data_.size())));
}

template <class T>
T vnl_vector<T>::min_value() const {
  assert(!data_.empty());
  T smallest = data_[0];
  for (const T& x : data_) {
    if (x < smallest) smallest = x;
  }
  return smallest;
}

template <class T>
T vnl_vector<T>::max_value() const {
  assert(!data_.empty());
  T largest = data_[0];
  for (const T& x : data_) {
    if (x > largest) largest = x;
  }
  return largest;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::normalize() {
  const T norm = two_norm();
  if (norm != T(0)) *this /= norm;
  return *this;
}

template <class T>
T dot_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == b.size());
  T total(0);
  for (std::size_t i = 0; i < a.size(); ++i) total += a[i] * b[i];
  return total;
}

template <class T>
vnl_vector<T> element_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == b.size());
  vnl_vector<T> result(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) result[i] = a[i] * b[i];
  return result;
}

template <class T>
vnl_vector<T> vnl_cross_3d(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == 3 && b.size() == 3);
  vnl_vector<T> result(3);
  result[0] = a[1] * b[2] - a[2] * b[1];
  result[1] = a[2] * b[0] - a[0] * b[2];
  result[2] = a[0] * b[1] - a[1] * b[0];
  return result;
}

template <class T>
T vnl_vector_ssd(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == b.size());
  T total(0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const T d = a[i] - b[i];
    total += d * d;
  }
  return total;
}

template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_vector<T>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s << ' ';
    s << static_cast<double>(v[i]);
  }
  return s;
}

/// Explicitly instantiates vnl_vector<T> and its free functions (used by instances/).
#define VNL_VECTOR_INSTANTIATE(T)                                                     \
  template class vnl_vector<T>;                                                       \
  template T dot_product(const vnl_vector<T>&, const vnl_vector<T>&);                 \
  template vnl_vector<T> element_product(const vnl_vector<T>&, const vnl_vector<T>&); \
  template vnl_vector<T> vnl_cross_3d(const vnl_vector<T>&, const vnl_vector<T>&);    \
  template T vnl_vector_ssd(const vnl_vector<T>&, const vnl_vector<T>&);              \
  template std::ostream& operator<<(std::ostream&, const vnl_vector<T>&)
