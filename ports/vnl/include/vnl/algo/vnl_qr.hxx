// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_qr.h: Householder QR on T.
#pragma once

#include <cassert>
#include <cmath>

#include "vnl/algo/vnl_qr.h"
#include "vnl/vnl_math.h"

inline namespace edgetrack_ports {

template <class T>
vnl_qr<T>::vnl_qr(const vnl_matrix<T>& M) : Q_(M.rows(), M.rows()), R_(M) {
  using std::sqrt;
  const std::size_t m = M.rows(), n = M.cols();
  Q_.set_identity();
  vnl_vector<T> v(m);
  for (std::size_t k = 0; k < n && k + 1 < m; ++k) {
    // The reflection H = I - 2 v v^T / (v^T v) that zeroes R(k+1.., k).
    T scale(0);
    for (std::size_t i = k; i < m; ++i) scale = vnl_math::max(scale, vnl_math::abs(R_(i, k)));
    if (scale == T(0)) continue;
    T norm2(0);
    for (std::size_t i = k; i < m; ++i) {
      v[i] = R_(i, k) / scale;  // scaled so the squares stay in range (fixed point)
      norm2 += v[i] * v[i];
    }
    const T norm = sqrt(norm2);
    const T alpha = v[k] < T(0) ? norm : -norm;  // R(k, k) becomes alpha * scale
    v[k] -= alpha;
    T vtv(0);
    for (std::size_t i = k; i < m; ++i) vtv += v[i] * v[i];
    if (vtv == T(0)) continue;
    ++reflections_;
    for (std::size_t j = k; j < n; ++j) {  // R <- H R
      T dot(0);
      for (std::size_t i = k; i < m; ++i) dot += v[i] * R_(i, j);
      const T f = T(2) * dot / vtv;
      for (std::size_t i = k; i < m; ++i) R_(i, j) -= f * v[i];
    }
    for (std::size_t i = k + 1; i < m; ++i) R_(i, k) = T(0);
    for (std::size_t r = 0; r < m; ++r) {  // Q <- Q H
      T dot(0);
      for (std::size_t i = k; i < m; ++i) dot += Q_(r, i) * v[i];
      const T f = T(2) * dot / vtv;
      for (std::size_t i = k; i < m; ++i) Q_(r, i) -= f * v[i];
    }
  }
}

template <class T>
T vnl_qr<T>::determinant() const {
  assert(R_.rows() == R_.cols());
  T det = reflections_ % 2 == 0 ? T(1) : T(-1);
  for (std::size_t i = 0; i < R_.rows(); ++i) det *= R_(i, i);
  return det;
}

template <class T>
vnl_vector<T> vnl_qr<T>::solve(const vnl_vector<T>& rhs) const {
  const std::size_t n = R_.cols();
  assert(rhs.size() == Q_.rows() && R_.rows() >= n);
  const vnl_vector<T> y = QtB(rhs);
  vnl_vector<T> x(n);
  for (std::size_t ii = n; ii-- > 0;) {  // back substitution on R's top n x n block
    T total = y[ii];
    for (std::size_t j = ii + 1; j < n; ++j) total -= R_(ii, j) * x[j];
    x[ii] = total / R_(ii, ii);
  }
  return x;
}

template <class T>
vnl_matrix<T> vnl_qr<T>::solve(const vnl_matrix<T>& rhs) const {
  vnl_matrix<T> x(R_.cols(), rhs.cols());
  for (std::size_t c = 0; c < rhs.cols(); ++c) x.set_column(c, solve(rhs.get_column(c)));
  return x;
}

template <class T>
vnl_matrix<T> vnl_qr<T>::inverse() const {
  vnl_matrix<T> identity(Q_.rows(), Q_.rows());
  identity.set_identity();
  return solve(identity);
}

#define VNL_QR_INSTANTIATE(T) template class vnl_qr<T>

}  // inline namespace edgetrack_ports
