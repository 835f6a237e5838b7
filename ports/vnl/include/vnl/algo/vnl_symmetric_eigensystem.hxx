// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_symmetric_eigensystem.h: cyclic Jacobi on T.
#pragma once

#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "vnl/algo/vnl_jacobi_rotation.h"
#include "vnl/algo/vnl_symmetric_eigensystem.h"

inline namespace edgetrack_ports {

template <class T>
bool vnl_symmetric_eigensystem_compute(const vnl_matrix<T>& A, vnl_matrix<T>& V, vnl_vector<T>& D) {
  using std::sqrt;
  if (A.rows() != A.cols()) return false;
  const unsigned n = static_cast<unsigned>(A.rows());
  vnl_matrix<T> a(A);
  V.set_size(n, n);
  V.set_identity();
  const T eps = std::numeric_limits<T>::epsilon();
  const T large_zeta = T(1) / sqrt(eps);
  const T floor = vnl_jacobi::rounding_floor<T>(n);
  bool rotated = true;
  for (int sweep = 0; sweep < vnl_jacobi::kMaxSweeps && rotated; ++sweep) {
    rotated = false;
    for (unsigned p = 0; p + 1 < n; ++p) {
      for (unsigned q = p + 1; q < n; ++q) {
        const T apq = a(p, q);
        const T magnitude = vnl_math::abs(apq);
        if (magnitude <= floor ||
            magnitude <= eps * sqrt(vnl_math::abs(a(p, p))) * sqrt(vnl_math::abs(a(q, q))))
          continue;
        const T t = vnl_jacobi::tangent(a(p, p), a(q, q), apq, large_zeta);
        const T c = T(1) / sqrt(T(1) + t * t);
        const T s = c * t;
        a(p, p) -= t * apq;
        a(q, q) += t * apq;
        a(p, q) = a(q, p) = T(0);
        for (unsigned r = 0; r < n; ++r) {
          if (r != p && r != q) {
            const T arp = a(r, p), arq = a(r, q);
            a(r, p) = a(p, r) = c * arp - s * arq;
            a(r, q) = a(q, r) = s * arp + c * arq;
          }
          const T vrp = V(r, p), vrq = V(r, q);
          V(r, p) = c * vrp - s * vrq;
          V(r, q) = s * vrp + c * vrq;
        }
        rotated = true;
      }
    }
  }
  D.set_size(n);
  for (unsigned i = 0; i < n; ++i) D[i] = a(i, i);
  for (unsigned j = 0; j + 1 < n; ++j) {  // ascending, as EISPACK's rs returns them
    unsigned smallest = j;
    for (unsigned k = j + 1; k < n; ++k) {
      if (D[k] < D[smallest]) smallest = k;
    }
    if (smallest == j) continue;
    std::swap(D[j], D[smallest]);
    for (unsigned r = 0; r < n; ++r) std::swap(V(r, j), V(r, smallest));
  }
  return !rotated;
}

template <class T>
void vnl_symmetric_eigensystem_compute_eigenvals(T M11, T M12, T M13, T M22, T M23, T M33, T& l1, T& l2, T& l3) {
  vnl_matrix<T> m(3, 3);
  m(0, 0) = M11, m(0, 1) = m(1, 0) = M12, m(0, 2) = m(2, 0) = M13;
  m(1, 1) = M22, m(1, 2) = m(2, 1) = M23, m(2, 2) = M33;
  vnl_matrix<T> v;
  vnl_vector<T> d;
  vnl_symmetric_eigensystem_compute(m, v, d);
  l1 = d[0], l2 = d[1], l3 = d[2];
}

template <class T>
vnl_symmetric_eigensystem<T>::vnl_symmetric_eigensystem(const vnl_matrix<T>& M)
    : n(static_cast<int>(M.rows())), V(M.rows(), M.rows()), D(static_cast<unsigned>(M.rows())) {
  assert(M.rows() == M.cols());
  vnl_vector<T> d;
  vnl_symmetric_eigensystem_compute(M, V, d);
  D.set_diagonal(d);
}

template <class T>
vnl_matrix<T> vnl_symmetric_eigensystem<T>::pinverse() const {
  vnl_diag_matrix<T> inverse_d(D);
  inverse_d.invert_in_place();
  return V * inverse_d * V.transpose();
}

template <class T>
vnl_matrix<T> vnl_symmetric_eigensystem<T>::square_root() const {
  using std::sqrt;
  vnl_diag_matrix<T> root(D);
  for (T& d : root) d = d > T(0) ? T(sqrt(d)) : T(0);
  return V * root * V.transpose();
}

template <class T>
vnl_matrix<T> vnl_symmetric_eigensystem<T>::inverse_square_root() const {
  using std::sqrt;
  vnl_diag_matrix<T> root(D);
  for (T& d : root) d = d > T(0) ? T(T(1) / T(sqrt(d))) : T(0);
  return V * root * V.transpose();
}

template <class T>
vnl_vector<T> vnl_symmetric_eigensystem<T>::solve(const vnl_vector<T>& b) {
  vnl_vector<T> x = b * V;  // V^T b
  for (unsigned i = 0; i < x.size(); ++i) x[i] = D[i] == T(0) ? T(0) : T(x[i] / D[i]);
  return V * x;
}

#define VNL_SYMMETRIC_EIGENSYSTEM_INSTANTIATE(T)                                                   \
  template class vnl_symmetric_eigensystem<T>;                                                     \
  template bool vnl_symmetric_eigensystem_compute(const vnl_matrix<T>&, vnl_matrix<T>&, vnl_vector<T>&); \
  template void vnl_symmetric_eigensystem_compute_eigenvals(T, T, T, T, T, T, T&, T&, T&)

}  // inline namespace edgetrack_ports
