// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_vector.h: a heap-allocated vector of T with vnl's names and
/// meanings (size, set_size, data_block, two_norm, rms, dot_product...). Like upstream it may
/// instead view memory it does not own (vnl_vector_ref). Declarations only; vnl_vector.hxx
/// defines them and instances/ instantiates them for double, float, int, long, unsigned,
/// std::complex<double>, std::complex<float> and the configured `real`.
#pragma once

#ifdef vnl_vector_h_
#error "edgetrack's drop-in vnl/vnl_vector.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>
#include <initializer_list>
#include <iosfwd>

#include "vnl/vnl_c_vector.h"
#include "vnl/vnl_numeric_traits.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_matrix;
template <class T>
class vnl_vector_ref;

template <class T>
class vnl_vector {
 public:
  using element_type = T;
  using value_type = T;
  using size_type = std::size_t;
  using iterator = T*;
  using const_iterator = const T*;
  /// The type norms are returned in (upstream: unsigned for int, T for complex<T>).
  using abs_t = typename vnl_numeric_traits<T>::abs_t;

  vnl_vector() = default;
  /// n elements; upstream leaves them uninitialised, ours are zero.
  explicit vnl_vector(std::size_t n);
  vnl_vector(std::size_t n, const T& value);
  /// n elements, the first `count` of them copied from `values`, the rest zero.
  vnl_vector(std::size_t n, std::size_t count, const T values[]);
  /// Copies n elements from `data`.
  vnl_vector(const T* data, std::size_t n);
  vnl_vector(std::initializer_list<T> values);
  /// Views n elements at `data`; owns (and frees with delete[]) them only if `manage_own_memory`.
  vnl_vector(std::size_t n, T* data, bool manage_own_memory);
  vnl_vector(const vnl_vector& that);
  vnl_vector(vnl_vector&& that) noexcept;
  ~vnl_vector();

  /// Copies the values; a vector of another size takes the new size (a view must match).
  vnl_vector& operator=(const vnl_vector& rhs);
  vnl_vector& operator=(vnl_vector&& rhs);
  /// Sets every element to v.
  vnl_vector& operator=(const T& v) { return fill(v); }

  std::size_t size() const { return num_elmts_; }
  bool empty() const { return num_elmts_ == 0; }
  /// Resizes; the contents are zero afterwards (upstream: unspecified). Views cannot resize.
  bool set_size(std::size_t n);
  /// Makes the vector empty.
  void clear();

  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& operator()(std::size_t i) { return data_[i]; }
  const T& operator()(std::size_t i) const { return data_[i]; }
  T get(std::size_t i) const { return data_[i]; }
  void put(std::size_t i, const T& v) { data_[i] = v; }

  T* data_block() { return data_; }
  const T* data_block() const { return data_; }
  iterator begin() { return data_; }
  iterator end() { return data_ + num_elmts_; }
  const_iterator begin() const { return data_; }
  const_iterator end() const { return data_ + num_elmts_; }
  T& front() { return data_[0]; }
  const T& front() const { return data_[0]; }
  T& back() { return data_[num_elmts_ - 1]; }
  const T& back() const { return data_[num_elmts_ - 1]; }
  /// A view of this vector's memory.
  vnl_vector_ref<T> as_ref();
  const vnl_vector_ref<T> as_ref() const;

  vnl_vector& fill(const T& value);
  /// Copies size() elements from `data`.
  vnl_vector& copy_in(const T* data);
  vnl_vector& set(const T* data) { return copy_in(data); }
  void copy_out(T* data) const;

  /// The scalar forms take T by value, as upstream, so v /= v[0] divides by the old v[0].
  vnl_vector& operator+=(T value);
  vnl_vector& operator-=(T value);
  vnl_vector& operator*=(T value);
  vnl_vector& operator/=(T value);
  vnl_vector& operator+=(const vnl_vector& rhs);
  vnl_vector& operator-=(const vnl_vector& rhs);
  /// *this = M * (*this).
  vnl_vector& pre_multiply(const vnl_matrix<T>& m);
  /// *this = (*this) * M, the vector as a row.
  vnl_vector& post_multiply(const vnl_matrix<T>& m);
  vnl_vector& operator*=(const vnl_matrix<T>& m) { return post_multiply(m); }

  vnl_vector operator+() const { return *this; }
  /// -x element by element; unsigned elements give their signed type, as upstream.
  vnl_vector<typename vnl_numeric_traits<T>::signed_t> operator-() const;
  vnl_vector operator+(const T& v) const;
  vnl_vector operator-(const T& v) const;
  vnl_vector operator*(const T& v) const;
  vnl_vector operator/(const T& v) const;
  vnl_vector operator+(const vnl_vector& v) const;
  vnl_vector operator-(const vnl_vector& v) const;
  /// The row vector times M.
  vnl_vector operator*(const vnl_matrix<T>& m) const;

  /// f applied to each element.
  vnl_vector apply(T (*f)(T)) const;
  vnl_vector apply(T (*f)(const T&)) const;
  /// The n elements starting at `start`.
  vnl_vector extract(std::size_t n, std::size_t start = 0) const;
  /// Writes `v` into this vector starting at `start`.
  vnl_vector& update(const vnl_vector& v, std::size_t start = 0);

  /// Sum of |x_i|^2.
  abs_t squared_magnitude() const;
  abs_t magnitude() const { return two_norm(); }
  abs_t one_norm() const;
  abs_t two_norm() const;
  abs_t inf_norm() const;
  /// Divides by two_norm() unless the norm is zero.
  vnl_vector& normalize();
  /// Root mean square of the elements, sqrt(squared_magnitude / size).
  abs_t rms() const;
  T min_value() const;
  T max_value() const;
  /// Index of the smallest (largest) element, the first one on ties.
  std::size_t arg_min() const;
  std::size_t arg_max() const;
  T mean() const;
  T sum() const;

  /// Reverses the elements (all, or those in [b, e)).
  vnl_vector& flip();
  vnl_vector& flip(const std::size_t& b, const std::size_t& e);
  /// Element i moves to (i + shift) mod size(); a copy, or in place.
  vnl_vector roll(const int& shift) const;
  vnl_vector& roll_inplace(const int& shift);
  /// Swaps contents with `that` (both must own their memory).
  void swap(vnl_vector& that) noexcept;

  /// Aborts with a message unless size() == sz.
  void assert_size(std::size_t sz) const;
  /// Aborts with a message unless every element is finite.
  void assert_finite() const;
  bool is_finite() const;
  bool is_zero() const;
  bool has_nans() const;
  /// Every |this_i - rhs_i| <= tol.
  bool is_equal(const vnl_vector& rhs, double tol) const;
  bool operator_eq(const vnl_vector& v) const;
  bool operator==(const vnl_vector& that) const { return operator_eq(that); }
  bool operator!=(const vnl_vector& that) const { return !operator_eq(that); }

  /// Reads size() values (all whitespace-separated values when the vector is empty).
  bool read_ascii(std::istream& s);
  static vnl_vector read(std::istream& s);
  /// Prints the elements separated by spaces.
  void print(std::ostream& s) const;

 protected:
  /// Points at n elements at `data`; frees the old memory if it was owned.
  void protected_set_data(T* data, std::size_t n, bool manage_own_memory);

 private:
  void destroy();

  T* data_ = nullptr;
  std::size_t num_elmts_ = 0;
  bool own_memory_ = true;
};

template <class T>
vnl_vector<T> operator+(const T& s, const vnl_vector<T>& v) {
  return v + s;
}
template <class T>
vnl_vector<T> operator-(const T& s, const vnl_vector<T>& v) {
  return -(v - s);
}
template <class T>
vnl_vector<T> operator*(const T& s, const vnl_vector<T>& v) {
  return v * s;
}

template <class T>
T dot_product(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// sum a_i * conj(b_i) (the dot product for real T).
template <class T>
T inner_product(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// u^T A v.
template <class T>
T bracket(const vnl_vector<T>& u, const vnl_matrix<T>& a, const vnl_vector<T>& v);
template <class T>
vnl_vector<T> element_product(const vnl_vector<T>& a, const vnl_vector<T>& b);
template <class T>
vnl_vector<T> element_quotient(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// <a, b> / (|a| |b|), in T as upstream.
template <class T>
T cos_angle(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// The angle between a and b in radians, in [0, pi].
template <class T>
double angle(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// a x b of the first two elements of a and b (each at least 2 long), a scalar.
template <class T>
T vnl_cross_2d(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// Cross product of two 3-vectors.
template <class T>
vnl_vector<T> vnl_cross_3d(const vnl_vector<T>& a, const vnl_vector<T>& b);
/// Sum of squared differences of a and b.
template <class T>
typename vnl_numeric_traits<T>::abs_t vnl_vector_ssd(const vnl_vector<T>& a, const vnl_vector<T>& b);

template <class T>
void swap(vnl_vector<T>& a, vnl_vector<T>& b) noexcept {
  a.swap(b);
}

/// Prints the elements separated by spaces, as upstream does.
template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_vector<T>& v);
/// Reads whitespace-separated values (see read_ascii).
template <class T>
std::istream& operator>>(std::istream& s, vnl_vector<T>& v);

}  // inline namespace edgetrack_ports
