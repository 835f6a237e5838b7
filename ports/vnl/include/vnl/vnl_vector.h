// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_vector.h: a heap-allocated vector of T with vnl's names and
/// meanings (size, set_size, data_block, two_norm, rms, dot_product...). Declarations only;
/// vnl_vector.hxx defines them and instances/ instantiates them for the configured `real`.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <vector>

template <class T>
class vnl_matrix;

template <class T>
class vnl_vector {
 public:
  using element_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  vnl_vector() = default;
  explicit vnl_vector(std::size_t n);
  vnl_vector(std::size_t n, const T& value);
  /// Copies n elements from `data`.
  vnl_vector(const T* data, std::size_t n);

  std::size_t size() const { return data_.size(); }
  /// Resizes; like upstream, the contents are unspecified afterwards (we zero them).
  bool set_size(std::size_t n);
  void clear() { data_.clear(); }

  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& operator()(std::size_t i) { return data_[i]; }
  const T& operator()(std::size_t i) const { return data_[i]; }
  T get(std::size_t i) const { return data_[i]; }
  void put(std::size_t i, const T& v) { data_[i] = v; }

  T* data_block() { return data_.data(); }
  const T* data_block() const { return data_.data(); }
  iterator begin() { return data_.data(); }
  iterator end() { return data_.data() + data_.size(); }
  const_iterator begin() const { return data_.data(); }
  const_iterator end() const { return data_.data() + data_.size(); }

  vnl_vector& fill(const T& value);
  /// Copies size() elements from `data`.
  vnl_vector& copy_in(const T* data);
  void copy_out(T* data) const;

  vnl_vector& operator+=(const vnl_vector& rhs);
  vnl_vector& operator-=(const vnl_vector& rhs);
  vnl_vector& operator+=(const T& value);
  vnl_vector& operator-=(const T& value);
  vnl_vector& operator*=(const T& value);
  vnl_vector& operator/=(const T& value);
  vnl_vector operator-() const;

  /// The n elements starting at `start`.
  vnl_vector extract(std::size_t n, std::size_t start = 0) const;
  /// Writes `v` into this vector starting at `start`.
  vnl_vector& update(const vnl_vector& v, std::size_t start = 0);

  T sum() const;
  T mean() const;
  T squared_magnitude() const;
  T magnitude() const { return two_norm(); }
  T one_norm() const;
  T two_norm() const;
  T inf_norm() const;
  /// Root mean square of the elements, sqrt(squared_magnitude / size).
  T rms() const;
  T min_value() const;
  T max_value() const;
  /// Divides by two_norm() unless the norm is zero.
  vnl_vector& normalize();

  bool operator==(const vnl_vector& rhs) const { return data_ == rhs.data_; }
  bool operator!=(const vnl_vector& rhs) const { return !(*this == rhs); }

 private:
  std::vector<T> data_;
};

template <class T>
vnl_vector<T> operator+(vnl_vector<T> a, const vnl_vector<T>& b) {
  return a += b;
}
template <class T>
vnl_vector<T> operator-(vnl_vector<T> a, const vnl_vector<T>& b) {
  return a -= b;
}
template <class T>
vnl_vector<T> operator*(vnl_vector<T> v, const T& s) {
  return v *= s;
}
template <class T>
vnl_vector<T> operator*(const T& s, vnl_vector<T> v) {
  return v *= s;
}
template <class T>
vnl_vector<T> operator/(vnl_vector<T> v, const T& s) {
  return v /= s;
}

template <class T>
T dot_product(const vnl_vector<T>& a, const vnl_vector<T>& b);
template <class T>
T inner_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  return dot_product(a, b);
}
template <class T>
vnl_vector<T> element_product(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// Cross product of two 3-vectors.
template <class T>
vnl_vector<T> vnl_cross_3d(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// Sum of squared differences of a and b.
template <class T>
T vnl_vector_ssd(const vnl_vector<T>& a, const vnl_vector<T>& b);

/// Prints the elements separated by spaces, as upstream does.
template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_vector<T>& v);
