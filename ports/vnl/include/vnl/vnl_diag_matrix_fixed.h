// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_diag_matrix_fixed.h: an N x N diagonal matrix held by value as
/// its diagonal (vnl_diag_matrix with a size fixed at compile time). Header-only.
#pragma once

#ifdef vnl_diag_matrix_fixed_h_
#error "edgetrack's drop-in vnl/vnl_diag_matrix_fixed.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <ostream>

#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T, unsigned int N>
class vnl_diag_matrix_fixed {
 public:
  vnl_diag_matrix_fixed() = default;
  explicit vnl_diag_matrix_fixed(const T& value) : diagonal_(value) {}
  explicit vnl_diag_matrix_fixed(const vnl_vector_fixed<T, N>& that) : diagonal_(that) {}

  vnl_diag_matrix_fixed& operator*=(T v) {
    diagonal_ *= v;
    return *this;
  }
  vnl_diag_matrix_fixed& operator/=(T v) {
    diagonal_ /= v;
    return *this;
  }
  /// 1 / d_i (zeros stay zero).
  vnl_diag_matrix_fixed& invert_in_place() {
    for (unsigned i = 0; i < N; ++i) diagonal_[i] = diagonal_[i] == T(0) ? T(0) : T(1) / diagonal_[i];
    return *this;
  }
  T determinant() const {
    T det(1);
    for (unsigned i = 0; i < N; ++i) det *= diagonal_[i];
    return det;
  }
  vnl_vector_fixed<T, N> solve(const vnl_vector_fixed<T, N>& b) const {
    vnl_vector_fixed<T, N> x;
    solve(b, &x);
    return x;
  }
  void solve(const vnl_vector_fixed<T, N>& b, vnl_vector_fixed<T, N>* out) const {
    for (unsigned i = 0; i < N; ++i) (*out)[i] = b[i] / diagonal_[i];
  }
  T operator()(unsigned i, unsigned j) const { return i == j ? diagonal_[i] : T(0); }
  /// A diagonal element, for writing (i must equal j), as upstream's.
  T& operator()(unsigned i, unsigned j) {
    assert(i == j);
    (void)j;
    return diagonal_[i];
  }
  T& operator()(unsigned i) { return diagonal_[i]; }
  const T& operator()(unsigned i) const { return diagonal_[i]; }
  T& operator[](unsigned i) { return diagonal_[i]; }
  const T& operator[](unsigned i) const { return diagonal_[i]; }
  static constexpr unsigned size() { return N; }
  static constexpr unsigned rows() { return N; }
  static constexpr unsigned cols() { return N; }
  static constexpr unsigned columns() { return N; }
  T get(unsigned r, unsigned c) const { return (*this)(r, c); }
  void put(unsigned r, unsigned c, const T& v) {
    assert(r == c);
    (void)c;
    diagonal_[r] = v;
  }
  vnl_diag_matrix_fixed& fill_diagonal(const T& v) {
    diagonal_.fill(v);
    return *this;
  }
  vnl_diag_matrix_fixed& set_diagonal(const vnl_vector_fixed<T, N>& v) {
    diagonal_ = v;
    return *this;
  }
  const vnl_vector_fixed<T, N>& get_diagonal() const { return diagonal_; }
  const vnl_vector_fixed<T, N>& diagonal() const { return diagonal_; }
  T* data_block() { return diagonal_.data_block(); }
  const T* data_block() const { return diagonal_.data_block(); }
  vnl_matrix_fixed<T, N, N> as_matrix() const {
    vnl_matrix_fixed<T, N, N> m(T(0));
    for (unsigned i = 0; i < N; ++i) m(i, i) = diagonal_[i];
    return m;
  }

 private:
  vnl_vector_fixed<T, N> diagonal_;
};

template <class T, unsigned N>
vnl_vector_fixed<T, N> operator*(const vnl_diag_matrix_fixed<T, N>& d, const vnl_vector_fixed<T, N>& v) {
  return element_product(d.diagonal(), v);
}
template <class T, unsigned N>
vnl_diag_matrix_fixed<T, N> operator*(const vnl_diag_matrix_fixed<T, N>& a, const vnl_diag_matrix_fixed<T, N>& b) {
  return vnl_diag_matrix_fixed<T, N>(element_product(a.diagonal(), b.diagonal()));
}
template <class T, unsigned N>
vnl_diag_matrix_fixed<T, N> operator+(const vnl_diag_matrix_fixed<T, N>& a, const vnl_diag_matrix_fixed<T, N>& b) {
  return vnl_diag_matrix_fixed<T, N>(a.diagonal() + b.diagonal());
}
template <class T, unsigned N>
vnl_diag_matrix_fixed<T, N> operator-(const vnl_diag_matrix_fixed<T, N>& a, const vnl_diag_matrix_fixed<T, N>& b) {
  return vnl_diag_matrix_fixed<T, N>(a.diagonal() - b.diagonal());
}
template <class T, unsigned N>
vnl_matrix_fixed<T, N, N> operator*(const vnl_matrix_fixed<T, N, N>& a, const vnl_diag_matrix_fixed<T, N>& d) {
  vnl_matrix_fixed<T, N, N> result(a);
  for (unsigned r = 0; r < N; ++r) {
    for (unsigned c = 0; c < N; ++c) result(r, c) *= d[c];
  }
  return result;
}
template <class T, unsigned N>
vnl_matrix_fixed<T, N, N> operator*(const vnl_diag_matrix_fixed<T, N>& d, const vnl_matrix_fixed<T, N, N>& a) {
  vnl_matrix_fixed<T, N, N> result(a);
  for (unsigned r = 0; r < N; ++r) {
    for (unsigned c = 0; c < N; ++c) result(r, c) *= d[r];
  }
  return result;
}

template <class T, unsigned N>
vnl_vector_fixed<T, N> operator*(const vnl_vector_fixed<T, N>& v, const vnl_diag_matrix_fixed<T, N>& d) {
  return element_product(v, d.diagonal());
}
/// Sums and differences with a full fixed matrix: the diagonal added to (taken from) it.
template <class T, unsigned N>
vnl_matrix_fixed<T, N, N> operator+(const vnl_diag_matrix_fixed<T, N>& d, vnl_matrix_fixed<T, N, N> a) {
  for (unsigned i = 0; i < N; ++i) a(i, i) += d[i];
  return a;
}
template <class T, unsigned N>
vnl_matrix_fixed<T, N, N> operator+(const vnl_matrix_fixed<T, N, N>& a, const vnl_diag_matrix_fixed<T, N>& d) {
  return d + a;
}
template <class T, unsigned N>
vnl_matrix_fixed<T, N, N> operator-(const vnl_matrix_fixed<T, N, N>& a, const vnl_diag_matrix_fixed<T, N>& d) {
  vnl_matrix_fixed<T, N, N> result(a);
  for (unsigned i = 0; i < N; ++i) result(i, i) -= d[i];
  return result;
}
template <class T, unsigned N>
vnl_matrix_fixed<T, N, N> operator-(const vnl_diag_matrix_fixed<T, N>& d, const vnl_matrix_fixed<T, N, N>& a) {
  return d + (-a);
}
/// Prints diag([ d0 d1 ... ]), as upstream.
template <class T, unsigned N>
std::ostream& operator<<(std::ostream& s, const vnl_diag_matrix_fixed<T, N>& d) {
  s << "diag([ ";
  for (unsigned i = 0; i < N; ++i) s << d[i] << ' ';
  return s << "])";
}

}  // inline namespace edgetrack_ports
