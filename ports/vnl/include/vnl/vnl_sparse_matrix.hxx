// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_sparse_matrix.h (upstream: core/vnl/vnl_sparse_matrix.hxx).
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>

#include "vnl/vnl_math.h"
#include "vnl/vnl_sparse_matrix.h"

inline namespace edgetrack_ports {

template <class T>
T& vnl_sparse_matrix<T>::operator()(unsigned int r, unsigned int c) {
  assert(r < rs_ && c < cs_);
  row& rw = elements_[r];
  auto it = std::lower_bound(rw.begin(), rw.end(), pair_t(c, T(0)), typename pair_t::less());
  if (it == rw.end() || it->first != c) it = rw.insert(it, pair_t(c, T(0)));
  return it->second;
}

template <class T>
T vnl_sparse_matrix<T>::get(unsigned int r, unsigned int c) const {
  assert(r < rs_ && c < cs_);
  const row& rw = elements_[r];
  const auto it = std::lower_bound(rw.begin(), rw.end(), pair_t(c, T(0)), typename pair_t::less());
  return (it == rw.end() || it->first != c) ? T(0) : it->second;
}

template <class T>
vnl_sparse_matrix<T>& vnl_sparse_matrix<T>::set_row(unsigned int r, const std::vector<int>& cols,
                                                    const std::vector<T>& vals) {
  assert(r < rs_ && cols.size() == vals.size());
  row& rw = elements_[r];
  rw.clear();
  for (std::size_t i = 0; i < cols.size(); ++i) rw.push_back(pair_t(static_cast<unsigned>(cols[i]), vals[i]));
  std::sort(rw.begin(), rw.end(), typename pair_t::less());
  return *this;
}

template <class T>
T vnl_sparse_matrix<T>::sum_row(unsigned int r) {
  T total(0);
  for (const pair_t& e : elements_[r]) total += e.second;
  return total;
}

template <class T>
void vnl_sparse_matrix<T>::scale_row(unsigned int r, T scale) {
  for (pair_t& e : elements_[r]) e.second *= scale;
}

template <class T>
vnl_sparse_matrix<T>& vnl_sparse_matrix<T>::vcat(const vnl_sparse_matrix& a) {
  if (rs_ == 0) {
    *this = a;
    return *this;
  }
  assert(a.cs_ == cs_);
  elements_.insert(elements_.end(), a.elements_.begin(), a.elements_.end());
  rs_ += a.rs_;
  return *this;
}

template <class T>
void vnl_sparse_matrix<T>::set_size(int r, int c) {
  elements_.assign(static_cast<std::size_t>(r), row());
  rs_ = static_cast<unsigned>(r);
  cs_ = static_cast<unsigned>(c);
}

template <class T>
void vnl_sparse_matrix<T>::resize(int r, int c) {
  elements_.resize(static_cast<std::size_t>(r));
  for (row& rw : elements_) {
    rw.erase(std::remove_if(rw.begin(), rw.end(), [c](const pair_t& e) { return e.first >= static_cast<unsigned>(c); }),
             rw.end());
  }
  rs_ = static_cast<unsigned>(r);
  cs_ = static_cast<unsigned>(c);
}

template <class T>
void vnl_sparse_matrix<T>::mult(const vnl_vector<T>& rhs, vnl_vector<T>& result) const {
  assert(rhs.size() == cs_);
  result.set_size(rs_);
  for (unsigned r = 0; r < rs_; ++r) {
    T total(0);
    for (const pair_t& e : elements_[r]) total += e.second * rhs[e.first];
    result[r] = total;
  }
}

template <class T>
void vnl_sparse_matrix<T>::mult(unsigned int n, unsigned int m, const T* p, T* q) const {
  assert(n == cs_);
  (void)n;
  for (unsigned r = 0; r < rs_; ++r) {
    for (unsigned j = 0; j < m; ++j) {
      T total(0);
      for (const pair_t& e : elements_[r]) total += e.second * p[e.first + j * n];
      q[r + j * rs_] = total;
    }
  }
}

template <class T>
void vnl_sparse_matrix<T>::pre_mult(const vnl_vector<T>& lhs, vnl_vector<T>& result) const {
  assert(lhs.size() == rs_);
  result.set_size(cs_);
  for (unsigned r = 0; r < rs_; ++r) {
    for (const pair_t& e : elements_[r]) result[e.first] += lhs[r] * e.second;
  }
}

template <class T>
void vnl_sparse_matrix<T>::mult(const vnl_sparse_matrix& rhs, vnl_sparse_matrix& result) const {
  assert(cs_ == rhs.rs_);
  result.set_size(static_cast<int>(rs_), static_cast<int>(rhs.cs_));
  std::vector<T> accumulator(rhs.cs_);
  std::vector<bool> touched(rhs.cs_);
  for (unsigned r = 0; r < rs_; ++r) {
    std::fill(accumulator.begin(), accumulator.end(), T(0));
    std::fill(touched.begin(), touched.end(), false);
    for (const pair_t& a : elements_[r]) {
      for (const pair_t& b : rhs.elements_[a.first]) {
        accumulator[b.first] += a.second * b.second;
        touched[b.first] = true;
      }
    }
    for (unsigned c = 0; c < rhs.cs_; ++c) {
      if (touched[c]) result.elements_[r].push_back(pair_t(c, accumulator[c]));
    }
  }
}

template <class T>
void vnl_sparse_matrix<T>::add(const vnl_sparse_matrix& rhs, vnl_sparse_matrix& result) const {
  assert(rs_ == rhs.rs_ && cs_ == rhs.cs_);
  vnl_sparse_matrix sum(rs_, cs_);
  for (unsigned r = 0; r < rs_; ++r) {
    const row& a = elements_[r];
    const row& b = rhs.elements_[r];
    row& out = sum.elements_[r];
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
      if (j == b.size() || (i < a.size() && a[i].first < b[j].first)) {
        out.push_back(a[i++]);
      } else if (i == a.size() || b[j].first < a[i].first) {
        out.push_back(b[j++]);
      } else {
        out.push_back(pair_t(a[i].first, a[i].second + b[j].second));
        ++i, ++j;
      }
    }
  }
  result = sum;
}

template <class T>
void vnl_sparse_matrix<T>::subtract(const vnl_sparse_matrix& rhs, vnl_sparse_matrix& result) const {
  add(-rhs, result);
}

template <class T>
void vnl_sparse_matrix<T>::diag_AtA(vnl_vector<T>& result) const {
  result.set_size(cs_);
  for (const row& rw : elements_) {
    for (const pair_t& e : rw) result[e.first] += vnl_math::conj(e.second) * e.second;
  }
}

template <class T>
vnl_vector<T> vnl_sparse_matrix<T>::operator*(const vnl_vector<T>& rhs) const {
  vnl_vector<T> result;
  mult(rhs, result);
  return result;
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::operator-() const {
  vnl_sparse_matrix result(*this);
  for (row& rw : result.elements_) {
    for (pair_t& e : rw) e.second = -e.second;
  }
  return result;
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::operator+(const vnl_sparse_matrix& rhs) const {
  vnl_sparse_matrix result;
  add(rhs, result);
  return result;
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::operator-(const vnl_sparse_matrix& rhs) const {
  vnl_sparse_matrix result;
  subtract(rhs, result);
  return result;
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::operator*(const vnl_sparse_matrix& rhs) const {
  vnl_sparse_matrix result;
  mult(rhs, result);
  return result;
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::operator*(const T& rhs) const {
  vnl_sparse_matrix result(*this);
  return result *= rhs;
}

template <class T>
vnl_sparse_matrix<T>& vnl_sparse_matrix<T>::operator*=(const T& rhs) {
  for (row& rw : elements_) {
    for (pair_t& e : rw) e.second *= rhs;
  }
  return *this;
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::operator/(const T& rhs) const {
  vnl_sparse_matrix result(*this);
  return result /= rhs;
}

template <class T>
vnl_sparse_matrix<T>& vnl_sparse_matrix<T>::operator/=(const T& rhs) {
  for (row& rw : elements_) {
    for (pair_t& e : rw) e.second /= rhs;
  }
  return *this;
}

template <class T>
bool vnl_sparse_matrix<T>::operator==(const vnl_sparse_matrix& rhs) const {
  return rs_ == rhs.rs_ && cs_ == rhs.cs_ && elements_ == rhs.elements_;
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::transpose() const {
  vnl_sparse_matrix result(cs_, rs_);
  for (unsigned r = 0; r < rs_; ++r) {
    for (const pair_t& e : elements_[r]) result.elements_[e.first].push_back(pair_t(r, e.second));
  }
  return result;  // rows were visited in order, so each new row is sorted
}

template <class T>
vnl_sparse_matrix<T> vnl_sparse_matrix<T>::conjugate_transpose() const {
  vnl_sparse_matrix result = transpose();
  for (row& rw : result.elements_) {
    for (pair_t& e : rw) e.second = vnl_math::conj(e.second);
  }
  return result;
}

template <class T>
vnl_sparse_matrix<T>& vnl_sparse_matrix<T>::set_identity() {
  assert(rs_ == cs_);
  for (unsigned r = 0; r < rs_; ++r) elements_[r] = row(1, pair_t(r, T(1)));
  return *this;
}

template <class T>
vnl_sparse_matrix<T>& vnl_sparse_matrix<T>::normalize_rows() {
  using std::sqrt;
  using abs_t = typename vnl_numeric_traits<T>::abs_t;
  for (row& rw : elements_) {
    abs_t total(0);
    for (const pair_t& e : rw) total += abs_t(vnl_math::squared_magnitude(e.second));
    if (total == abs_t(0)) continue;
    const abs_t norm = abs_t(sqrt(total));
    for (pair_t& e : rw) e.second = T(e.second / norm);
  }
  return *this;
}

template <class T>
void vnl_sparse_matrix<T>::reset() const {
  itr_is_reset_ = true;
  itr_row_ = 0;
  itr_index_ = 0;
}

template <class T>
bool vnl_sparse_matrix<T>::next() const {
  if (itr_is_reset_) {
    itr_is_reset_ = false;
    itr_row_ = 0;
    itr_index_ = 0;
  } else {
    ++itr_index_;
  }
  while (itr_row_ < rs_ && itr_index_ >= elements_[itr_row_].size()) {
    ++itr_row_;
    itr_index_ = 0;
  }
  return itr_row_ < rs_;
}

template <class T>
int vnl_sparse_matrix<T>::getrow() const {
  return static_cast<int>(itr_row_);
}

template <class T>
int vnl_sparse_matrix<T>::getcolumn() const {
  return static_cast<int>(elements_[itr_row_][itr_index_].first);
}

template <class T>
T vnl_sparse_matrix<T>::value() const {
  return elements_[itr_row_][itr_index_].second;
}

#define VNL_SPARSE_MATRIX_INSTANTIATE(T) template class vnl_sparse_matrix<T>

}  // inline namespace edgetrack_ports
