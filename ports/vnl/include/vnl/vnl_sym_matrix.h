// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_sym_matrix.h: a symmetric n x n matrix stored as its lower
/// triangle, row by row (n (n + 1) / 2 values). (i, j) and (j, i) are the same element;
/// operator[](i) is row i's i + 1 stored values. Header-only.
#pragma once

#ifdef vnl_sym_matrix_h_
#error "edgetrack's drop-in vnl/vnl_sym_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>
#include <cassert>
#include <ostream>
#include <utility>
#include <vector>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_sym_matrix {
 public:
  using iterator = T*;
  using const_iterator = const T*;

  vnl_sym_matrix() = default;
  /// n x n of zeros (upstream: uninitialised).
  explicit vnl_sym_matrix(unsigned nn) : data_(nn * (nn + 1) / 2, T(0)), nn_(nn) {}
  /// From the packed lower triangle, row by row.
  vnl_sym_matrix(const T* data, unsigned nn) : data_(data, data + nn * (nn + 1) / 2), nn_(nn) {}
  vnl_sym_matrix(unsigned nn, const T& value) : data_(nn * (nn + 1) / 2, value), nn_(nn) {}
  /// The lower triangle of a square matrix (the upper one is ignored).
  explicit vnl_sym_matrix(const vnl_matrix<T>& that) : vnl_sym_matrix(static_cast<unsigned>(that.rows())) {
    assert(that.rows() == that.cols());
    for (unsigned i = 0; i < nn_; ++i) {
      for (unsigned j = 0; j <= i; ++j) fast(i, j) = that(i, j);
    }
  }

  vnl_sym_matrix& operator*=(T v) {
    for (T& x : data_) x *= v;
    return *this;
  }
  vnl_sym_matrix& operator/=(T v) {
    for (T& x : data_) x /= v;
    return *this;
  }
  T operator()(unsigned i, unsigned j) const { return i >= j ? fast(i, j) : fast(j, i); }
  T& operator()(unsigned i, unsigned j) { return i >= j ? fast(i, j) : fast(j, i); }
  /// Row i of the lower triangle: its i + 1 values.
  const T* operator[](unsigned i) const {
    assert(i < nn_);
    return data_.data() + i * (i + 1) / 2;
  }
  /// (i, j) for i >= j, without the swap.
  T fast(unsigned i, unsigned j) const {
    assert(i >= j);
    return data_[i * (i + 1) / 2 + j];
  }
  T& fast(unsigned i, unsigned j) {
    assert(i >= j);
    return data_[i * (i + 1) / 2 + j];
  }
  iterator begin() { return data_.data(); }
  iterator end() { return data_.data() + data_.size(); }
  const_iterator begin() const { return data_.data(); }
  const_iterator end() const { return data_.data() + data_.size(); }
  T* data_block() { return data_.data(); }
  const T* data_block() const { return data_.data(); }

  /// The number of stored values, n (n + 1) / 2.
  unsigned int size() const { return static_cast<unsigned>(data_.size()); }
  unsigned int rows() const { return nn_; }
  unsigned int cols() const { return nn_; }
  unsigned int columns() const { return nn_; }
  void put(unsigned r, unsigned c, const T& v) { (*this)(r, c) = v; }
  T get(unsigned r, unsigned c) const { return (*this)(r, c); }

  /// The full n x n matrix.
  vnl_matrix<T> as_matrix() const {
    vnl_matrix<T> m(nn_, nn_);
    for (unsigned i = 0; i < nn_; ++i) {
      for (unsigned j = 0; j <= i; ++j) m(i, j) = m(j, i) = fast(i, j);
    }
    return m;
  }
  /// Resizes to n x n zeros.
  void set_size(int n) {
    nn_ = static_cast<unsigned>(n);
    data_.assign(nn_ * (nn_ + 1) / 2, T(0));
  }
  /// Row i up to the diagonal: (i, 0), ..., (i, i).
  vnl_vector<T> get_half_row(unsigned i) const { return vnl_vector<T>((*this)[i], i + 1); }
  void set_half_row(const vnl_vector<T>& half_row, unsigned i) {
    assert(half_row.size() == i + 1);
    for (unsigned j = 0; j <= i; ++j) fast(i, j) = half_row[j];
  }
  /// Writes m into the block whose diagonal starts at (diag_start, diag_start).
  vnl_sym_matrix& update(const vnl_sym_matrix& m, unsigned diag_start = 0) {
    assert(diag_start + m.nn_ <= nn_);
    for (unsigned i = 0; i < m.nn_; ++i) {
      for (unsigned j = 0; j <= i; ++j) fast(diag_start + i, diag_start + j) = m.fast(i, j);
    }
    return *this;
  }
  void swap(vnl_sym_matrix& m) noexcept {
    data_.swap(m.data_);
    std::swap(nn_, m.nn_);
  }
  vnl_sym_matrix& fill(const T& v) {
    for (T& x : data_) x = v;
    return *this;
  }

 private:
  std::vector<T> data_;
  unsigned nn_ = 0;
};

/// Exchanges the contents of a and b (found by argument-dependent lookup, as upstream's).
template <class T>
void swap(vnl_sym_matrix<T>& a, vnl_sym_matrix<T>& b) noexcept {
  a.swap(b);
}
template <class T>
bool operator==(const vnl_sym_matrix<T>& a, const vnl_sym_matrix<T>& b) {
  return a.rows() == b.rows() && std::equal(a.begin(), a.end(), b.begin());
}
template <class T>
bool operator!=(const vnl_sym_matrix<T>& a, const vnl_sym_matrix<T>& b) {
  return !(a == b);
}
/// Equal when b is square, symmetric and has a's values.
template <class T>
bool operator==(const vnl_sym_matrix<T>& a, const vnl_matrix<T>& b) {
  return b.rows() == a.rows() && b.cols() == a.cols() && a.as_matrix() == b;
}
template <class T>
bool operator==(const vnl_matrix<T>& a, const vnl_sym_matrix<T>& b) {
  return b == a;
}
/// True when a is square and a(i, j) == a(j, i).
template <class T>
bool is_symmetric(const vnl_matrix<T>& a) {
  if (a.rows() != a.cols()) return false;
  for (std::size_t i = 0; i < a.rows(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (!(a(i, j) == a(j, i))) return false;
    }
  }
  return true;
}
template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_sym_matrix<T>& m) {
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j <= i; ++j) s << (j ? " " : "") << m.fast(i, j);
    s << '\n';
  }
  return s;
}

}  // inline namespace edgetrack_ports
