// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_diag_matrix.h: an n x n diagonal matrix stored as its diagonal,
/// with the products, sums and solves that stay cheap on that form. Header-only.
#pragma once

#ifdef vnl_diag_matrix_h_
#error "edgetrack's drop-in vnl/vnl_diag_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <cstddef>
#include <ostream>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_diag_matrix {
 public:
  using iterator = typename vnl_vector<T>::iterator;
  using const_iterator = typename vnl_vector<T>::const_iterator;

  vnl_diag_matrix() = default;
  /// n x n with a zero diagonal (upstream: uninitialised).
  explicit vnl_diag_matrix(unsigned n) : diagonal_(n) {}
  vnl_diag_matrix(unsigned n, const T& value) : diagonal_(n, value) {}
  explicit vnl_diag_matrix(const vnl_vector<T>& that) : diagonal_(that) {}

  unsigned size() const { return static_cast<unsigned>(diagonal_.size()); }
  unsigned rows() const { return size(); }
  unsigned cols() const { return size(); }
  unsigned columns() const { return size(); }
  void set_size(int n) { diagonal_.set_size(static_cast<std::size_t>(n)); }
  void clear() { diagonal_.clear(); }

  /// Element (i, j): the diagonal value, or zero off the diagonal.
  T operator()(unsigned i, unsigned j) const { return i == j ? diagonal_[i] : T(0); }
  T& operator()(unsigned i, unsigned j) {
    assert(i == j);
    (void)j;
    return diagonal_[i];
  }
  T& operator()(unsigned i) { return diagonal_[i]; }
  const T& operator()(unsigned i) const { return diagonal_[i]; }
  T& operator[](unsigned i) { return diagonal_[i]; }
  const T& operator[](unsigned i) const { return diagonal_[i]; }
  T get(unsigned r, unsigned c) const { return (*this)(r, c); }
  void put(unsigned r, unsigned c, const T& v) {
    assert(r == c);
    diagonal_[r] = v;
  }

  const vnl_vector<T>& get_diagonal() const { return diagonal_; }
  const vnl_vector<T>& diagonal() const { return diagonal_; }
  vnl_diag_matrix& set_diagonal(const vnl_vector<T>& v) {
    diagonal_ = v;
    return *this;
  }
  vnl_diag_matrix& fill_diagonal(const T& v) {
    diagonal_.fill(v);
    return *this;
  }
  vnl_diag_matrix& fill(const T& v) { return fill_diagonal(v); }
  T* data_block() { return diagonal_.data_block(); }
  const T* data_block() const { return diagonal_.data_block(); }
  iterator begin() { return diagonal_.begin(); }
  iterator end() { return diagonal_.end(); }
  const_iterator begin() const { return diagonal_.begin(); }
  const_iterator end() const { return diagonal_.end(); }

  vnl_diag_matrix& operator*=(const T& v) {
    diagonal_ *= v;
    return *this;
  }
  vnl_diag_matrix& operator/=(const T& v) {
    diagonal_ /= v;
    return *this;
  }

  /// The full n x n matrix.
  vnl_matrix<T> as_matrix() const {
    vnl_matrix<T> m(size(), size(), T(0));
    m.set_diagonal(diagonal_);
    return m;
  }
  vnl_matrix<T> as_ref() const { return as_matrix(); }
  /// Replaces each d_i by 1/d_i (zeros stay zero, the pseudo-inverse).
  void invert_in_place() {
    for (T& d : diagonal_) d = d == T(0) ? T(0) : T(1) / d;
  }
  /// The product of the diagonal.
  T determinant() const {
    T det(1);
    for (const T& d : diagonal_) det *= d;
    return det;
  }
  /// x with D x = b.
  vnl_vector<T> solve(const vnl_vector<T>& b) const {
    vnl_vector<T> x(b.size());
    solve(b, &x);
    return x;
  }
  void solve(const vnl_vector<T>& b, vnl_vector<T>* out) const {
    assert(b.size() == size());
    for (unsigned i = 0; i < size(); ++i) (*out)[i] = b[i] / diagonal_[i];
  }

 private:
  vnl_vector<T> diagonal_;
};

template <class T>
vnl_matrix<T> operator*(const vnl_matrix<T>& a, const vnl_diag_matrix<T>& d) {
  assert(a.cols() == d.size());
  vnl_matrix<T> result(a);
  for (unsigned c = 0; c < d.size(); ++c) result.scale_column(c, d[c]);
  return result;
}
template <class T>
vnl_matrix<T> operator*(const vnl_diag_matrix<T>& d, const vnl_matrix<T>& a) {
  assert(a.rows() == d.size());
  vnl_matrix<T> result(a);
  for (unsigned r = 0; r < d.size(); ++r) result.scale_row(r, d[r]);
  return result;
}
template <class T>
vnl_diag_matrix<T> operator*(const vnl_diag_matrix<T>& a, const vnl_diag_matrix<T>& b) {
  return vnl_diag_matrix<T>(element_product(a.diagonal(), b.diagonal()));
}
template <class T>
vnl_vector<T> operator*(const vnl_diag_matrix<T>& d, const vnl_vector<T>& v) {
  return element_product(d.diagonal(), v);
}
template <class T>
vnl_vector<T> operator*(const vnl_vector<T>& v, const vnl_diag_matrix<T>& d) {
  return element_product(v, d.diagonal());
}
template <class T>
vnl_matrix<T> operator+(const vnl_matrix<T>& a, const vnl_diag_matrix<T>& d) {
  vnl_matrix<T> result(a);
  for (unsigned i = 0; i < d.size(); ++i) result(i, i) += d[i];
  return result;
}
template <class T>
vnl_matrix<T> operator+(const vnl_diag_matrix<T>& d, const vnl_matrix<T>& a) {
  return a + d;
}
template <class T>
vnl_diag_matrix<T> operator+(const vnl_diag_matrix<T>& a, const vnl_diag_matrix<T>& b) {
  return vnl_diag_matrix<T>(a.diagonal() + b.diagonal());
}
template <class T>
vnl_matrix<T> operator-(const vnl_matrix<T>& a, const vnl_diag_matrix<T>& d) {
  vnl_matrix<T> result(a);
  for (unsigned i = 0; i < d.size(); ++i) result(i, i) -= d[i];
  return result;
}
template <class T>
vnl_matrix<T> operator-(const vnl_diag_matrix<T>& d, const vnl_matrix<T>& a) {
  vnl_matrix<T> result(-a);
  for (unsigned i = 0; i < d.size(); ++i) result(i, i) += d[i];
  return result;
}
template <class T>
vnl_diag_matrix<T> operator-(const vnl_diag_matrix<T>& a, const vnl_diag_matrix<T>& b) {
  return vnl_diag_matrix<T>(a.diagonal() - b.diagonal());
}
template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_diag_matrix<T>& d) {
  return s << d.diagonal();
}

}  // inline namespace edgetrack_ports
