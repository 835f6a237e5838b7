// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_cholesky.h.
#pragma once

#include <cassert>
#include <cmath>
#include <cstdio>

#include "vnl/algo/vnl_cholesky.h"
#include "vnl/vnl_math.h"

inline namespace edgetrack_ports {

template <class T>
vnl_cholesky_of<T>::vnl_cholesky_of(const vnl_matrix<T>& M, Operation mode) : L_(M.rows(), M.cols()) {
  using std::sqrt;
  const std::size_t n = M.rows();
  assert(M.cols() == n);
  for (std::size_t j = 0; j < n; ++j) {
    T d = M(j, j);
    for (std::size_t k = 0; k < j; ++k) d -= L_(j, k) * L_(j, k);
    if (!(d > T(0))) {
      num_dims_rank_def_ = static_cast<int>(j + 1);
      if (mode == verbose) std::fprintf(stderr, "vnl_cholesky: leading minor %d is not positive definite\n",
                                        num_dims_rank_def_);
      return;
    }
    const T l = sqrt(d);
    L_(j, j) = l;
    for (std::size_t i = j + 1; i < n; ++i) {
      T s = M(i, j);
      for (std::size_t k = 0; k < j; ++k) s -= L_(i, k) * L_(j, k);
      L_(i, j) = s / l;
    }
  }
  if (mode == estimate_condition && n > 0) {
    const vnl_matrix<T> inv = inverse();
    const T norms = M.operator_one_norm() * inv.operator_one_norm();
    rcond_ = norms == T(0) ? T(0) : T(1) / norms;
    // The column of M^-1 with the largest norm is the direction M shrinks most.
    std::size_t best = 0;
    T best_norm(0);
    for (std::size_t c = 0; c < n; ++c) {
      const T norm = inv.get_column(c).one_norm();
      if (norm > best_norm) best_norm = norm, best = c;
    }
    nullvector_ = inv.get_column(best).normalize();
  }
}

template <class T>
void vnl_cholesky_of<T>::solve(const vnl_vector<T>& b, vnl_vector<T>* x) const {
  const std::size_t n = L_.rows();
  assert(b.size() == n);
  vnl_vector<T> y(b);
  for (std::size_t i = 0; i < n; ++i) {  // L y = b
    for (std::size_t k = 0; k < i; ++k) y[i] -= L_(i, k) * y[k];
    y[i] /= L_(i, i);
  }
  for (std::size_t i = n; i-- > 0;) {  // L^T x = y
    for (std::size_t k = i + 1; k < n; ++k) y[i] -= L_(k, i) * y[k];
    y[i] /= L_(i, i);
  }
  *x = y;
}

template <class T>
vnl_vector<T> vnl_cholesky_of<T>::solve(const vnl_vector<T>& b) const {
  vnl_vector<T> x(b.size());
  solve(b, &x);
  return x;
}

template <class T>
T vnl_cholesky_of<T>::determinant() const {
  T det(1);
  for (std::size_t i = 0; i < L_.rows(); ++i) det *= L_(i, i) * L_(i, i);
  return det;
}

template <class T>
vnl_matrix<T> vnl_cholesky_of<T>::inverse() const {
  const std::size_t n = L_.rows();
  vnl_matrix<T> result(n, n);
  vnl_vector<T> e(n), x(n);
  for (std::size_t c = 0; c < n; ++c) {
    e.fill(T(0));
    e[c] = T(1);
    solve(e, &x);
    result.set_column(c, x);
  }
  return result;
}

template <class T>
vnl_matrix<T> vnl_cholesky_of<T>::lower_triangle() const {
  return L_;
}

template <class T>
vnl_matrix<T> vnl_cholesky_of<T>::upper_triangle() const {
  return L_.transpose();
}

#define VNL_CHOLESKY_INSTANTIATE(T) template class vnl_cholesky_of<T>

}  // inline namespace edgetrack_ports
