// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_complex_eigensystem.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "inverse_iteration.h"

inline namespace edgetrack_ports {

namespace {

using C = std::complex<double>;

/// Reduces h to upper Hessenberg form by Householder reflections (unitary similarities).
void reduce_to_hessenberg(vnl_matrix<C>& h) {
  const unsigned n = h.rows();
  std::vector<C> v(n);
  for (unsigned k = 0; k + 2 < n; ++k) {
    double norm = 0;
    for (unsigned i = k + 1; i < n; ++i) norm += std::norm(h(i, k));
    norm = std::sqrt(norm);
    if (norm == 0) continue;
    const C x0 = h(k + 1, k);
    const C alpha = -(std::abs(x0) > 0 ? x0 / std::abs(x0) : C(1)) * norm;
    for (unsigned i = k + 1; i < n; ++i) v[i] = h(i, k);
    v[k + 1] -= alpha;
    double vv = 0;
    for (unsigned i = k + 1; i < n; ++i) vv += std::norm(v[i]);
    if (vv == 0) continue;
    for (unsigned j = 0; j < n; ++j) {  // h = (I - 2 v v^H / v^H v) h
      C s = 0;
      for (unsigned i = k + 1; i < n; ++i) s += std::conj(v[i]) * h(i, j);
      s *= 2 / vv;
      for (unsigned i = k + 1; i < n; ++i) h(i, j) -= s * v[i];
    }
    for (unsigned i = 0; i < n; ++i) {  // h = h (I - 2 v v^H / v^H v)
      C s = 0;
      for (unsigned j = k + 1; j < n; ++j) s += h(i, j) * v[j];
      s *= 2 / vv;
      for (unsigned j = k + 1; j < n; ++j) h(i, j) -= s * std::conj(v[j]);
    }
    for (unsigned i = k + 2; i < n; ++i) h(i, k) = 0;
  }
}

/// One shifted QR step H - mu = QR, H = RQ + mu on rows and columns lo..hi, by Givens rotations.
void qr_step(vnl_matrix<C>& h, unsigned lo, unsigned hi, C mu) {
  std::vector<C> cs(hi - lo), sn(hi - lo);
  for (unsigned k = lo; k <= hi; ++k) h(k, k) -= mu;
  for (unsigned k = lo; k < hi; ++k) {
    const C x = h(k, k), y = h(k + 1, k);
    const double r = std::sqrt(std::norm(x) + std::norm(y));
    const C c = r > 0 ? x / r : C(1), s = r > 0 ? y / r : C(0);
    cs[k - lo] = c;
    sn[k - lo] = s;
    for (unsigned j = k; j <= hi; ++j) {  // rows k, k+1 by [[conj c, conj s], [-s, c]]
      const C a = h(k, j), b = h(k + 1, j);
      h(k, j) = std::conj(c) * a + std::conj(s) * b;
      h(k + 1, j) = -s * a + c * b;
    }
  }
  for (unsigned k = lo; k < hi; ++k) {  // columns k, k+1 by the adjoint rotation
    const C c = cs[k - lo], s = sn[k - lo];
    for (unsigned i = lo; i <= k + 1; ++i) {
      const C a = h(i, k), b = h(i, k + 1);
      h(i, k) = a * c + b * s;
      h(i, k + 1) = -a * std::conj(s) + b * std::conj(c);
    }
  }
  for (unsigned k = lo; k <= hi; ++k) h(k, k) += mu;
}

/// The eigenvalues of the Hessenberg h (destroyed); false when QR does not converge.
bool hessenberg_eigenvalues(vnl_matrix<C>& h, std::vector<C>& eigenvalues) {
  const unsigned n = h.rows();
  const double eps = std::numeric_limits<double>::epsilon();
  int hi = static_cast<int>(n) - 1, iterations = 0;
  while (hi >= 0) {
    int lo = hi;
    while (lo > 0 && std::abs(h(lo, lo - 1)) > eps * (std::abs(h(lo - 1, lo - 1)) + std::abs(h(lo, lo)))) --lo;
    if (lo > 0) h(lo, lo - 1) = 0;
    if (lo == hi) {
      eigenvalues.push_back(h(hi, hi));
      --hi;
      iterations = 0;
      continue;
    }
    if (++iterations > 300) return false;
    // Wilkinson's shift: the eigenvalue of the trailing 2 x 2 block nearer its last entry.
    const C a = h(hi - 1, hi - 1), b = h(hi - 1, hi), c = h(hi, hi - 1), d = h(hi, hi);
    const C half = (a - d) / 2.0, root = std::sqrt(half * half + b * c);
    const C mu1 = d + half + root, mu2 = d + half - root;
    C mu = std::abs(mu1 - d) < std::abs(mu2 - d) ? mu1 : mu2;
    if (iterations % 20 == 0) mu = d + std::abs(c) * C(0.75, 0.5);  // an exceptional shift breaks a cycle
    qr_step(h, static_cast<unsigned>(lo), static_cast<unsigned>(hi), mu);
  }
  return true;
}

}  // namespace

vnl_complex_eigensystem::vnl_complex_eigensystem(const vnl_matrix<double>& A_real, const vnl_matrix<double>& A_imag,
                                                 bool right, bool left)
    : N(A_real.rows()) {
  vnl_matrix<C> A(N, N);
  for (unsigned i = 0; i < N; ++i)
    for (unsigned j = 0; j < N; ++j) A(i, j) = C(A_real(i, j), A_imag(i, j));
  compute(A, right, left);
}

vnl_complex_eigensystem::vnl_complex_eigensystem(const vnl_matrix<C>& A, bool right, bool left) : N(A.rows()) {
  compute(A, right, left);
}

void vnl_complex_eigensystem::compute(const vnl_matrix<C>& A, bool right, bool left) {
  W.set_size(N);
  if (right) R.set_size(N, N);
  if (left) L.set_size(N, N);
  if (N == 0 || A.cols() != N) return;
  vnl_matrix<C> h = A;
  reduce_to_hessenberg(h);
  std::vector<C> eigenvalues;
  if (!hessenberg_eigenvalues(h, eigenvalues)) {
    std::cerr << "vnl_complex_eigensystem: the QR iteration did not converge\n";
    return;
  }
  double norm = 0;
  for (unsigned j = 0; j < N; ++j) {
    double column = 0;
    for (unsigned i = 0; i < N; ++i) column += std::abs(A(i, j));
    norm = std::max(norm, column);
  }
  const vnl_matrix<C> At = A.transpose();  // l A = w l is A^T l^T = w l^T
  for (unsigned k = 0; k < N; ++k) {
    W[k] = eigenvalues[k];
    if (right) R.set_row(k, vnl_algo_detail::inverse_iteration(A, W[k], norm));
    if (left) L.set_row(k, vnl_algo_detail::inverse_iteration(At, W[k], norm));
  }
}

}  // inline namespace edgetrack_ports
