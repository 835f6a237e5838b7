// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_vector_fixed.h: a vector of n T's held by value (no heap), with
/// vnl_vector's names. Header-only: every size is instantiated where it is used.
#pragma once

#ifdef vnl_vector_fixed_h_
#error "edgetrack's drop-in vnl/vnl_vector_fixed.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <utility>

#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_ref.h"

inline namespace edgetrack_ports {

template <class T, unsigned int n>
class vnl_vector_fixed {
 public:
  using element_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  /// Like upstream, the default value is all zeros here (upstream leaves it uninitialised).
  vnl_vector_fixed() { fill(T(0)); }
  explicit vnl_vector_fixed(const T& value) { fill(value); }
  explicit vnl_vector_fixed(const T* data) { copy_in(data); }
  vnl_vector_fixed(const T& x, const T& y) {
    static_assert(n == 2, "two values for a 2-vector");
    data_[0] = x;
    data_[1] = y;
  }
  vnl_vector_fixed(const T& x, const T& y, const T& z) {
    static_assert(n == 3, "three values for a 3-vector");
    data_[0] = x;
    data_[1] = y;
    data_[2] = z;
  }
  vnl_vector_fixed(const T& x, const T& y, const T& z, const T& w) {
    static_assert(n == 4, "four values for a 4-vector");
    data_[0] = x;
    data_[1] = y;
    data_[2] = z;
    data_[3] = w;
  }
  /// From a vnl_vector of the same size (implicit, as upstream's).
  vnl_vector_fixed(const vnl_vector<T>& v) {
    assert(v.size() == n);
    copy_in(v.data_block());
  }

  static constexpr std::size_t size() { return n; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& operator()(std::size_t i) { return data_[i]; }
  const T& operator()(std::size_t i) const { return data_[i]; }
  T get(std::size_t i) const { return data_[i]; }
  void put(std::size_t i, const T& v) { data_[i] = v; }
  T* data_block() { return data_; }
  const T* data_block() const { return data_; }
  iterator begin() { return data_; }
  iterator end() { return data_ + n; }
  const_iterator begin() const { return data_; }
  const_iterator end() const { return data_ + n; }

  vnl_vector_fixed& fill(const T& value) {
    for (T& x : data_) x = value;
    return *this;
  }
  vnl_vector_fixed& copy_in(const T* data) {
    for (unsigned i = 0; i < n; ++i) data_[i] = data[i];
    return *this;
  }
  void copy_out(T* data) const {
    for (unsigned i = 0; i < n; ++i) data[i] = data_[i];
  }
  /// A heap copy, for code written against vnl_vector.
  vnl_vector<T> as_vector() const { return vnl_vector<T>(data_, n); }
  /// A vnl_vector viewing this vector's elements (valid while this vector lives).
  vnl_vector_ref<T> as_ref() { return vnl_vector_ref<T>(n, data_); }
  const vnl_vector_ref<T> as_ref() const { return vnl_vector_ref<T>(n, const_cast<T*>(data_)); }
  /// As upstream's default (VXL_USE_HISTORICAL_IMPLICIT_CONVERSIONS): a fixed vector passes
  /// where a const vnl_vector& is expected, as a view of its elements.
  operator const vnl_vector_ref<T>() const { return as_ref(); }
  explicit operator vnl_vector<T>() const { return as_vector(); }
  T& front() { return data_[0]; }
  const T& front() const { return data_[0]; }
  T& back() { return data_[n - 1]; }
  const T& back() const { return data_[n - 1]; }
  /// Writes the elements separated by single spaces, as vnl_vector.
  void print(std::ostream& s) const { s << as_ref(); }
  /// Reads n whitespace-separated values; false if the stream ran out.
  bool read_ascii(std::istream& s) { return as_ref().read_ascii(s); }

  vnl_vector_fixed& operator+=(const vnl_vector_fixed& rhs) {
    for (unsigned i = 0; i < n; ++i) data_[i] += rhs.data_[i];
    return *this;
  }
  vnl_vector_fixed& operator-=(const vnl_vector_fixed& rhs) {
    for (unsigned i = 0; i < n; ++i) data_[i] -= rhs.data_[i];
    return *this;
  }
  vnl_vector_fixed& operator+=(T s) {
    for (T& x : data_) x += s;
    return *this;
  }
  vnl_vector_fixed& operator-=(T s) {
    for (T& x : data_) x -= s;
    return *this;
  }
  vnl_vector_fixed& operator*=(T s) {
    for (T& x : data_) x *= s;
    return *this;
  }
  vnl_vector_fixed& operator/=(T s) {
    for (T& x : data_) x /= s;
    return *this;
  }
  vnl_vector_fixed& operator+=(const vnl_vector<T>& rhs) {
    assert(rhs.size() == n);
    for (unsigned i = 0; i < n; ++i) data_[i] += rhs[i];
    return *this;
  }
  vnl_vector_fixed& operator-=(const vnl_vector<T>& rhs) {
    assert(rhs.size() == n);
    for (unsigned i = 0; i < n; ++i) data_[i] -= rhs[i];
    return *this;
  }
  /// -x element by element; unsigned elements give their signed type, as upstream.
  vnl_vector_fixed<typename vnl_numeric_traits<T>::signed_t, n> operator-() const {
    using signed_t = typename vnl_numeric_traits<T>::signed_t;
    vnl_vector_fixed<signed_t, n> result;
    for (unsigned i = 0; i < n; ++i) result[i] = -signed_t(data_[i]);
    return result;
  }
  vnl_vector_fixed& set(const T* data) { return copy_in(data); }
  vnl_vector_fixed apply(T (*f)(T)) const { return applied(f); }
  vnl_vector_fixed apply(T (*f)(const T&)) const { return applied(f); }
  /// The len elements from `start`.
  vnl_vector<T> extract(unsigned len, unsigned start = 0) const {
    assert(start + len <= n);
    return vnl_vector<T>(data_ + start, len);
  }
  /// Writes v from position `start` on.
  vnl_vector_fixed& update(const vnl_vector<T>& v, unsigned start = 0) {
    assert(start + v.size() <= n);
    for (unsigned i = 0; i < v.size(); ++i) data_[start + i] = v[i];
    return *this;
  }
  vnl_vector_fixed& flip() {
    for (unsigned i = 0; i < n / 2; ++i) std::swap(data_[i], data_[n - 1 - i]);
    return *this;
  }
  typename vnl_vector<T>::abs_t rms() const { return as_ref().rms(); }
  T min_value() const { return as_ref().min_value(); }
  T max_value() const { return as_ref().max_value(); }
  unsigned arg_min() const { return unsigned(as_ref().arg_min()); }
  unsigned arg_max() const { return unsigned(as_ref().arg_max()); }
  T mean() const { return as_ref().mean(); }
  bool is_finite() const { return as_ref().is_finite(); }
  bool is_zero() const { return as_ref().is_zero(); }
  bool is_equal(const vnl_vector_fixed& rhs, double tol) const { return as_ref().is_equal(rhs.as_ref(), tol); }
  void assert_size(unsigned sz) const {
    assert(sz == n);
    (void)sz;
  }
  void assert_finite() const { as_ref().assert_finite(); }
  static constexpr bool empty() { return n == 0; }

  T squared_magnitude() const {
    T total(0);
    for (const T& x : data_) total += x * x;
    return total;
  }
  T two_norm() const {
    using std::sqrt;
    return sqrt(squared_magnitude());
  }
  T magnitude() const { return two_norm(); }
  T one_norm() const {
    using std::abs;
    T total(0);
    for (const T& x : data_) total += abs(x);
    return total;
  }
  T inf_norm() const {
    using std::abs;
    T largest(0);
    for (const T& x : data_) {
      if (abs(x) > largest) largest = abs(x);
    }
    return largest;
  }
  T sum() const {
    T total(0);
    for (const T& x : data_) total += x;
    return total;
  }
  vnl_vector_fixed& normalize() {
    const T norm = two_norm();
    if (norm != T(0)) *this /= norm;
    return *this;
  }

  bool operator==(const vnl_vector_fixed& rhs) const {
    for (unsigned i = 0; i < n; ++i) {
      if (data_[i] != rhs.data_[i]) return false;
    }
    return true;
  }
  bool operator!=(const vnl_vector_fixed& rhs) const { return !(*this == rhs); }

 private:
  template <class F>
  vnl_vector_fixed applied(F f) const {
    vnl_vector_fixed result;
    for (unsigned i = 0; i < n; ++i) result[i] = f(data_[i]);
    return result;
  }

  T data_[n];
};

template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator+(vnl_vector_fixed<T, n> a, const vnl_vector_fixed<T, n>& b) {
  return a += b;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator-(vnl_vector_fixed<T, n> a, const vnl_vector_fixed<T, n>& b) {
  return a -= b;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator+(vnl_vector_fixed<T, n> v, const T& s) {
  return v += s;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator+(const T& s, vnl_vector_fixed<T, n> v) {
  return v += s;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator-(vnl_vector_fixed<T, n> v, const T& s) {
  return v -= s;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator-(const T& s, const vnl_vector_fixed<T, n>& v) {
  return -v + s;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator*(vnl_vector_fixed<T, n> v, const T& s) {
  return v *= s;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator*(const T& s, vnl_vector_fixed<T, n> v) {
  return v *= s;
}
template <class T, unsigned int n>
vnl_vector_fixed<T, n> operator/(vnl_vector_fixed<T, n> v, const T& s) {
  return v /= s;
}

template <class T, unsigned int n>
T dot_product(const vnl_vector_fixed<T, n>& a, const vnl_vector_fixed<T, n>& b) {
  T total(0);
  for (unsigned i = 0; i < n; ++i) total += a[i] * b[i];
  return total;
}

template <class T, unsigned int n>
vnl_vector_fixed<T, n> element_product(const vnl_vector_fixed<T, n>& a, const vnl_vector_fixed<T, n>& b) {
  vnl_vector_fixed<T, n> result;
  for (unsigned i = 0; i < n; ++i) result[i] = a[i] * b[i];
  return result;
}

template <class T, unsigned int n>
vnl_vector_fixed<T, n> element_quotient(const vnl_vector_fixed<T, n>& a, const vnl_vector_fixed<T, n>& b) {
  vnl_vector_fixed<T, n> result;
  for (unsigned i = 0; i < n; ++i) result[i] = a[i] / b[i];
  return result;
}

/// Sum of squared differences, as vnl_vector's.
template <class T, unsigned int n>
typename vnl_numeric_traits<T>::abs_t vnl_vector_ssd(const vnl_vector_fixed<T, n>& a, const vnl_vector_fixed<T, n>& b) {
  return vnl_vector_ssd(a.as_ref(), b.as_ref());
}
template <class T, unsigned int n>
typename vnl_numeric_traits<T>::abs_t vnl_vector_ssd(const vnl_vector_fixed<T, n>& a, const vnl_vector<T>& b) {
  return vnl_vector_ssd(a.as_ref(), b);
}
template <class T, unsigned int n>
typename vnl_numeric_traits<T>::abs_t vnl_vector_ssd(const vnl_vector<T>& a, const vnl_vector_fixed<T, n>& b) {
  return vnl_vector_ssd(a, b.as_ref());
}

template <class T>
vnl_vector_fixed<T, 3> vnl_cross_3d(const vnl_vector_fixed<T, 3>& a, const vnl_vector_fixed<T, 3>& b) {
  return vnl_vector_fixed<T, 3>(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

using vnl_double_2 = vnl_vector_fixed<double, 2>;
using vnl_double_3 = vnl_vector_fixed<double, 3>;
using vnl_double_4 = vnl_vector_fixed<double, 4>;

template <class T, unsigned int n>
std::ostream& operator<<(std::ostream& s, const vnl_vector_fixed<T, n>& v) {
  v.print(s);
  return s;
}
template <class T, unsigned int n>
std::istream& operator>>(std::istream& s, vnl_vector_fixed<T, n>& v) {
  v.read_ascii(s);
  return s;
}

}  // inline namespace edgetrack_ports
