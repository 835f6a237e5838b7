// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_vector.h (upstream: core/vnl/vnl_vector.hxx). Include it only to
/// instantiate vnl_vector for a scalar that the library does not instantiate.
#pragma once

#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <type_traits>
#include <utility>
#include <vector>

#include "vnl/vnl_complex_traits.h"
#include "vnl/vnl_math.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_ref.h"

inline namespace edgetrack_ports {

namespace vnl_detail {
/// Writes one element as upstream prints it; fixed point prints as a double (I/O only).
template <class T>
void print_element(std::ostream& s, const T& x) {
  if constexpr (std::is_arithmetic_v<T> || !vnl_complex_traits<T>::isreal) {
    s << x;
  } else {
    s << static_cast<double>(x);
  }
}
/// Reads one element; fixed point reads a double and converts it (I/O only).
template <class T>
bool read_element(std::istream& s, T& x) {
  if constexpr (std::is_arithmetic_v<T> || !vnl_complex_traits<T>::isreal) {
    return static_cast<bool>(s >> x);
  } else {
    double d;
    if (!(s >> d)) return false;
    x = T(d);
    return true;
  }
}
/// The square root of a norm, taken in the norm type's real_t as upstream (double for the
/// integers and vnl_rational, the type itself for float, double and fixed point).
template <class A>
A root(const A& x) {
  using std::sqrt;
  using real_t = typename vnl_numeric_traits<A>::real_t;
  return A(sqrt(real_t(x)));
}
/// The order min_value and arg_min use: <, or the magnitude for complex values.
template <class T>
bool less(const T& a, const T& b) {
  if constexpr (vnl_complex_traits<T>::isreal) {
    return a < b;
  } else {
    return std::abs(a) < std::abs(b);
  }
}
}  // namespace vnl_detail

template <class T>
vnl_vector<T>::vnl_vector(std::size_t n) : vnl_vector(n, T(0)) {}

template <class T>
vnl_vector<T>::vnl_vector(std::size_t n, const T& value)
    : data_(n ? new T[n] : nullptr), num_elmts_(n) {
  fill(value);
}

template <class T>
vnl_vector<T>::vnl_vector(std::size_t n, std::size_t count, const T values[]) : vnl_vector(n) {
  for (std::size_t i = 0; i < count && i < n; ++i) data_[i] = values[i];
}

template <class T>
vnl_vector<T>::vnl_vector(const T* data, std::size_t n) : data_(n ? new T[n] : nullptr), num_elmts_(n) {
  copy_in(data);
}

template <class T>
vnl_vector<T>::vnl_vector(std::initializer_list<T> values) : vnl_vector(values.begin(), values.size()) {}

template <class T>
vnl_vector<T>::vnl_vector(std::size_t n, T* data, bool manage_own_memory)
    : data_(data), num_elmts_(n), own_memory_(manage_own_memory) {}

template <class T>
vnl_vector<T>::vnl_vector(const vnl_vector& that) : vnl_vector(that.data_, that.num_elmts_) {}

template <class T>
vnl_vector<T>::vnl_vector(vnl_vector&& that) noexcept : vnl_vector() {
  if (that.own_memory_) {
    swap(that);
  } else {  // a view keeps its memory; we take a copy
    *this = that;
  }
}

template <class T>
vnl_vector<T>::~vnl_vector() {
  destroy();
}

template <class T>
void vnl_vector<T>::destroy() {
  if (own_memory_) delete[] data_;
  data_ = nullptr;
  num_elmts_ = 0;
  own_memory_ = true;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator=(const vnl_vector& rhs) {
  if (this == &rhs) return *this;
  if (num_elmts_ != rhs.num_elmts_) {
    assert(own_memory_ && "a vnl_vector_ref cannot change size");
    set_size(rhs.num_elmts_);
  }
  return copy_in(rhs.data_);
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator=(vnl_vector&& rhs) {
  if (this == &rhs) return *this;
  if (own_memory_ && rhs.own_memory_) {
    swap(rhs);
    return *this;
  }
  return *this = static_cast<const vnl_vector&>(rhs);
}

template <class T>
bool vnl_vector<T>::set_size(std::size_t n) {
  if (!own_memory_) {
    assert(n == num_elmts_ && "a vnl_vector_ref cannot change size");
    return n == num_elmts_;
  }
  if (n != num_elmts_) {
    delete[] data_;
    data_ = n ? new T[n] : nullptr;
    num_elmts_ = n;
  }
  fill(T(0));
  return true;
}

template <class T>
void vnl_vector<T>::clear() {
  if (own_memory_) destroy();
}

template <class T>
void vnl_vector<T>::protected_set_data(T* data, std::size_t n, bool manage_own_memory) {
  destroy();
  data_ = data;
  num_elmts_ = n;
  own_memory_ = manage_own_memory;
}

template <class T>
vnl_vector_ref<T> vnl_vector<T>::as_ref() {
  return vnl_vector_ref<T>(num_elmts_, data_);
}

template <class T>
const vnl_vector_ref<T> vnl_vector<T>::as_ref() const {
  return vnl_vector_ref<T>(num_elmts_, const_cast<T*>(data_));
}

template <class T>
vnl_vector<T>& vnl_vector<T>::fill(const T& value) {
  for (std::size_t i = 0; i < num_elmts_; ++i) data_[i] = value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::copy_in(const T* data) {
  for (std::size_t i = 0; i < num_elmts_; ++i) data_[i] = data[i];
  return *this;
}

template <class T>
void vnl_vector<T>::copy_out(T* data) const {
  for (std::size_t i = 0; i < num_elmts_; ++i) data[i] = data_[i];
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator+=(T value) {
  for (T& x : *this) x += value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator-=(T value) {
  for (T& x : *this) x -= value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator*=(T value) {
  for (T& x : *this) x *= value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator/=(T value) {
  for (T& x : *this) x /= value;
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator+=(const vnl_vector& rhs) {
  assert(rhs.size() == size());
  for (std::size_t i = 0; i < num_elmts_; ++i) data_[i] += rhs.data_[i];
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::operator-=(const vnl_vector& rhs) {
  assert(rhs.size() == size());
  for (std::size_t i = 0; i < num_elmts_; ++i) data_[i] -= rhs.data_[i];
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::pre_multiply(const vnl_matrix<T>& m) {
  return *this = m * *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::post_multiply(const vnl_matrix<T>& m) {
  return *this = *this * m;
}

template <class T>
vnl_vector<typename vnl_numeric_traits<T>::signed_t> vnl_vector<T>::operator-() const {
  using signed_t = typename vnl_numeric_traits<T>::signed_t;
  vnl_vector<signed_t> result(size());
  signed_t* out = result.data_block();
  for (std::size_t i = 0; i < num_elmts_; ++i) out[i] = -static_cast<signed_t>(data_[i]);
  return result;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator+(const T& v) const {
  vnl_vector result(*this);
  return result += v;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator-(const T& v) const {
  vnl_vector result(*this);
  return result -= v;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator*(const T& v) const {
  vnl_vector result(*this);
  return result *= v;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator/(const T& v) const {
  vnl_vector result(*this);
  return result /= v;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator+(const vnl_vector& v) const {
  vnl_vector result(*this);
  return result += v;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator-(const vnl_vector& v) const {
  vnl_vector result(*this);
  return result -= v;
}

template <class T>
vnl_vector<T> vnl_vector<T>::operator*(const vnl_matrix<T>& m) const {
  assert(m.rows() == size());
  vnl_vector result(m.cols());
  for (std::size_t c = 0; c < m.cols(); ++c) {
    T total(0);
    for (std::size_t r = 0; r < m.rows(); ++r) total += data_[r] * m(r, c);
    result[c] = total;
  }
  return result;
}

template <class T>
vnl_vector<T> vnl_vector<T>::apply(T (*f)(T)) const {
  vnl_vector result(size());
  for (std::size_t i = 0; i < num_elmts_; ++i) result[i] = f(data_[i]);
  return result;
}

template <class T>
vnl_vector<T> vnl_vector<T>::apply(T (*f)(const T&)) const {
  vnl_vector result(size());
  for (std::size_t i = 0; i < num_elmts_; ++i) result[i] = f(data_[i]);
  return result;
}

template <class T>
vnl_vector<T> vnl_vector<T>::extract(std::size_t n, std::size_t start) const {
  assert(start + n <= size());
  return vnl_vector(data_ + start, n);
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
  for (const T& x : *this) total += x;
  return total;
}

template <class T>
T vnl_vector<T>::mean() const {
  return empty() ? T(0) : sum() / T(static_cast<int>(num_elmts_));
}

template <class T>
typename vnl_vector<T>::abs_t vnl_vector<T>::squared_magnitude() const {
  abs_t total(0);
  for (const T& x : *this) total += abs_t(vnl_math::squared_magnitude(x));
  return total;
}

template <class T>
typename vnl_vector<T>::abs_t vnl_vector<T>::one_norm() const {
  abs_t total(0);
  for (const T& x : *this) total += abs_t(vnl_math::abs(x));
  return total;
}

template <class T>
typename vnl_vector<T>::abs_t vnl_vector<T>::two_norm() const {
  return vnl_detail::root(squared_magnitude());
}

template <class T>
typename vnl_vector<T>::abs_t vnl_vector<T>::inf_norm() const {
  abs_t largest(0);
  for (const T& x : *this) {
    const abs_t a = abs_t(vnl_math::abs(x));
    if (a > largest) largest = a;
  }
  return largest;
}

template <class T>
typename vnl_vector<T>::abs_t vnl_vector<T>::rms() const {
  return empty() ? abs_t(0) : vnl_detail::root(abs_t(squared_magnitude() / abs_t(static_cast<int>(num_elmts_))));
}

template <class T>
T vnl_vector<T>::min_value() const {
  return data_[arg_min()];
}

template <class T>
T vnl_vector<T>::max_value() const {
  return data_[arg_max()];
}

template <class T>
std::size_t vnl_vector<T>::arg_min() const {
  assert(!empty());
  std::size_t best = 0;
  for (std::size_t i = 1; i < num_elmts_; ++i) {
    if (vnl_detail::less(data_[i], data_[best])) best = i;
  }
  return best;
}

template <class T>
std::size_t vnl_vector<T>::arg_max() const {
  assert(!empty());
  std::size_t best = 0;
  for (std::size_t i = 1; i < num_elmts_; ++i) {
    if (vnl_detail::less(data_[best], data_[i])) best = i;
  }
  return best;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::normalize() {
  const abs_t norm = two_norm();
  if (norm != abs_t(0)) {
    for (T& x : *this) x = T(x / norm);
  }
  return *this;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::flip() {
  return flip(0, num_elmts_);
}

template <class T>
vnl_vector<T>& vnl_vector<T>::flip(const std::size_t& b, const std::size_t& e) {
  assert(b <= e && e <= num_elmts_);
  for (std::size_t i = b, j = e; i + 1 < j; ++i, --j) std::swap(data_[i], data_[j - 1]);
  return *this;
}

template <class T>
vnl_vector<T> vnl_vector<T>::roll(const int& shift) const {
  vnl_vector result(size());
  const long n = static_cast<long>(num_elmts_);
  for (long i = 0; i < n; ++i) result[static_cast<std::size_t>(((i + shift) % n + n) % n)] = data_[i];
  return result;
}

template <class T>
vnl_vector<T>& vnl_vector<T>::roll_inplace(const int& shift) {
  const vnl_vector rolled = roll(shift);
  return copy_in(rolled.data_);
}

template <class T>
void vnl_vector<T>::swap(vnl_vector& that) noexcept {
  std::swap(data_, that.data_);
  std::swap(num_elmts_, that.num_elmts_);
  std::swap(own_memory_, that.own_memory_);
}

template <class T>
void vnl_vector<T>::assert_size(std::size_t sz) const {
  if (sz != num_elmts_) {
    std::fprintf(stderr, "vnl_vector: size is %zu, expected %zu\n", num_elmts_, sz);
    std::abort();
  }
}

template <class T>
void vnl_vector<T>::assert_finite() const {
  if (!is_finite()) {
    std::fprintf(stderr, "vnl_vector: an element is not finite\n");
    std::abort();
  }
}

template <class T>
bool vnl_vector<T>::is_finite() const {
  for (const T& x : *this) {
    if (!vnl_math::isfinite(x)) return false;
  }
  return true;
}

template <class T>
bool vnl_vector<T>::has_nans() const {
  for (const T& x : *this) {
    if (vnl_math::isnan(x)) return true;
  }
  return false;
}

template <class T>
bool vnl_vector<T>::is_zero() const {
  for (const T& x : *this) {
    if (!(x == T(0))) return false;
  }
  return true;
}

template <class T>
bool vnl_vector<T>::is_equal(const vnl_vector& rhs, double tol) const {
  if (rhs.size() != size()) return false;
  for (std::size_t i = 0; i < num_elmts_; ++i) {
    if (!(static_cast<double>(vnl_math::abs(data_[i] - rhs.data_[i])) <= tol)) return false;  // NaN is unequal
  }
  return true;
}

template <class T>
bool vnl_vector<T>::operator_eq(const vnl_vector& v) const {
  if (v.size() != size()) return false;
  for (std::size_t i = 0; i < num_elmts_; ++i) {
    if (!(data_[i] == v.data_[i])) return false;
  }
  return true;
}

template <class T>
bool vnl_vector<T>::read_ascii(std::istream& s) {
  if (!empty()) {
    for (T& x : *this) {
      if (!vnl_detail::read_element(s, x)) return false;
    }
    return true;
  }
  std::vector<T> values;
  T x;
  while (vnl_detail::read_element(s, x)) values.push_back(x);
  set_size(values.size());
  copy_in(values.data());
  return true;
}

template <class T>
vnl_vector<T> vnl_vector<T>::read(std::istream& s) {
  vnl_vector result;
  result.read_ascii(s);
  return result;
}

template <class T>
void vnl_vector<T>::print(std::ostream& s) const {
  s << *this << '\n';
}

template <class T>
T dot_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == b.size());
  T total(0);
  for (std::size_t i = 0; i < a.size(); ++i) total += a[i] * b[i];
  return total;
}

template <class T>
T inner_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == b.size());
  T total(0);
  for (std::size_t i = 0; i < a.size(); ++i) total += a[i] * vnl_math::conj(b[i]);
  return total;
}

template <class T>
T bracket(const vnl_vector<T>& u, const vnl_matrix<T>& a, const vnl_vector<T>& v) {
  return dot_product(u, a * v);
}

template <class T>
vnl_vector<T> element_product(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == b.size());
  vnl_vector<T> result(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) result[i] = a[i] * b[i];
  return result;
}

template <class T>
vnl_vector<T> element_quotient(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() == b.size());
  vnl_vector<T> result(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) result[i] = a[i] / b[i];
  return result;
}

template <class T>
T cos_angle(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  using real_t = typename vnl_numeric_traits<T>::real_t;
  using abs_r = typename vnl_numeric_traits<typename vnl_numeric_traits<T>::abs_t>::real_t;
  using std::sqrt;
  const real_t ab = real_t(inner_product(a, b));
  const real_t norms = real_t(sqrt(abs_r(a.squared_magnitude() * b.squared_magnitude())));
  return T(ab / norms);
}

template <class T>
double angle(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  using abs_r = typename vnl_numeric_traits<typename vnl_numeric_traits<T>::abs_t>::real_t;
  const abs_r c = abs_r(cos_angle(a, b));
  if (c >= abs_r(1)) return 0;
  if (c <= abs_r(-1)) return vnl_math::pi;
  using std::acos;  // fixed point finds its own acos
  return static_cast<double>(acos(c));
}

template <class T>
T vnl_cross_2d(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  assert(a.size() >= 2 && b.size() >= 2);  // as upstream: the first two elements of longer vectors
  return a[0] * b[1] - a[1] * b[0];
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
typename vnl_numeric_traits<T>::abs_t vnl_vector_ssd(const vnl_vector<T>& a, const vnl_vector<T>& b) {
  using abs_t = typename vnl_numeric_traits<T>::abs_t;
  assert(a.size() == b.size());
  abs_t total(0);
  for (std::size_t i = 0; i < a.size(); ++i) total += abs_t(vnl_math::squared_magnitude(a[i] - b[i]));
  return total;
}

template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_vector<T>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s << ' ';
    vnl_detail::print_element(s, v[i]);
  }
  return s;
}

template <class T>
std::istream& operator>>(std::istream& s, vnl_vector<T>& v) {
  v.read_ascii(s);
  return s;
}

/// Explicitly instantiates vnl_vector<T> and its free functions (used by instances/).
#define VNL_VECTOR_INSTANTIATE(T)                                                                      \
  template class vnl_vector<T>;                                                                        \
  template T dot_product(const vnl_vector<T>&, const vnl_vector<T>&);                                  \
  template T inner_product(const vnl_vector<T>&, const vnl_vector<T>&);                                \
  template T bracket(const vnl_vector<T>&, const vnl_matrix<T>&, const vnl_vector<T>&);                \
  template vnl_vector<T> element_product(const vnl_vector<T>&, const vnl_vector<T>&);                  \
  template vnl_vector<T> element_quotient(const vnl_vector<T>&, const vnl_vector<T>&);                 \
  template T vnl_cross_2d(const vnl_vector<T>&, const vnl_vector<T>&);                                 \
  template vnl_vector<T> vnl_cross_3d(const vnl_vector<T>&, const vnl_vector<T>&);                     \
  template vnl_numeric_traits<T>::abs_t vnl_vector_ssd(const vnl_vector<T>&, const vnl_vector<T>&);    \
  template std::ostream& operator<<(std::ostream&, const vnl_vector<T>&);                              \
  template std::istream& operator>>(std::istream&, vnl_vector<T>&)

}  // inline namespace edgetrack_ports
