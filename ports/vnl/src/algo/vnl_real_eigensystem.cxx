// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_real_eigensystem.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "inverse_iteration.h"

inline namespace edgetrack_ports {

namespace {

using C = std::complex<double>;

/// Reduces a to upper Hessenberg form by Householder reflections (similarity transforms).
void reduce_to_hessenberg(vnl_matrix<double>& a) {
  const int n = static_cast<int>(a.rows());
  std::vector<double> v(static_cast<size_t>(n));
  for (int k = 0; k + 2 < n; ++k) {
    double norm = 0;
    for (int i = k + 1; i < n; ++i) norm += a(i, k) * a(i, k);
    norm = std::sqrt(norm);
    if (norm == 0) continue;
    const double alpha = a(k + 1, k) > 0 ? -norm : norm;
    for (int i = k + 1; i < n; ++i) v[i] = a(i, k);
    v[k + 1] -= alpha;
    double vv = 0;
    for (int i = k + 1; i < n; ++i) vv += v[i] * v[i];
    if (vv == 0) continue;
    // a = (I - 2 v v^T / v.v) a (I - 2 v v^T / v.v)
    for (int j = 0; j < n; ++j) {
      double s = 0;
      for (int i = k + 1; i < n; ++i) s += v[i] * a(i, j);
      s *= 2 / vv;
      for (int i = k + 1; i < n; ++i) a(i, j) -= s * v[i];
    }
    for (int i = 0; i < n; ++i) {
      double s = 0;
      for (int j = k + 1; j < n; ++j) s += a(i, j) * v[j];
      s *= 2 / vv;
      for (int j = k + 1; j < n; ++j) a(i, j) -= s * v[j];
    }
    for (int i = k + 2; i < n; ++i) a(i, k) = 0;
  }
}

/// One Francis double-shift QR sweep on rows/columns lo..hi of the Hessenberg h, with the
/// shifts' sum x + y and product x y - w given as the trailing 2 x 2 block's.
void francis_step(vnl_matrix<double>& h, int lo, int hi, double x, double y, double w) {
  // The first column of (H - s1)(H - s2), from the top of the active block.
  double p = (h(lo, lo) - x) * (h(lo, lo) - y) - w + h(lo, lo + 1) * h(lo + 1, lo);
  double q = h(lo + 1, lo) * (h(lo, lo) + h(lo + 1, lo + 1) - x - y);
  double r = lo + 2 <= hi ? h(lo + 2, lo + 1) * h(lo + 1, lo) : 0;
  for (int k = lo; k <= hi - 1; ++k) {
    const int rows = k + 2 <= hi ? 3 : 2;
    if (k > lo) {
      p = h(k, k - 1);
      q = h(k + 1, k - 1);
      r = rows == 3 ? h(k + 2, k - 1) : 0;
    }
    const double scale = std::fabs(p) + std::fabs(q) + std::fabs(r);
    if (scale == 0) continue;
    p /= scale, q /= scale, r /= scale;
    const double norm = std::copysign(std::sqrt(p * p + q * q + r * r), p);
    // Reflector I - 2 u u^T / u.u with u = (p + norm, q, r), written as I - u (u / beta)^T.
    const double u0 = p + norm, beta = norm * u0;
    const double u[3] = {u0, q, r};
    if (k > lo) {
      h(k, k - 1) = -norm * scale;
      h(k + 1, k - 1) = 0;
      if (rows == 3) h(k + 2, k - 1) = 0;
    }
    const int first_col = k > lo ? k : lo;
    for (int j = first_col; j <= hi; ++j) {
      double s = 0;
      for (int t = 0; t < rows; ++t) s += u[t] * h(k + t, j);
      s /= beta;
      for (int t = 0; t < rows; ++t) h(k + t, j) -= s * u[t];
    }
    const int last_row = std::min(hi, k + 3);
    for (int i = lo; i <= last_row; ++i) {
      double s = 0;
      for (int t = 0; t < rows; ++t) s += h(i, k + t) * u[t];
      s /= beta;
      for (int t = 0; t < rows; ++t) h(i, k + t) -= s * u[t];
    }
  }
}

/// The eigenvalues of the Hessenberg h (destroyed); false when QR does not converge.
bool hessenberg_eigenvalues(vnl_matrix<double>& h, std::vector<C>& eigenvalues) {
  const int n = static_cast<int>(h.rows());
  double norm = 0;
  for (int i = 0; i < n; ++i)
    for (int j = std::max(i - 1, 0); j < n; ++j) norm += std::fabs(h(i, j));
  const double eps = std::numeric_limits<double>::epsilon();
  int hi = n - 1;
  int iterations = 0;
  while (hi >= 0) {
    int lo = hi;  // the top of the unreduced block ending at hi
    while (lo > 0) {
      double s = std::fabs(h(lo - 1, lo - 1)) + std::fabs(h(lo, lo));
      if (s == 0) s = norm;
      if (std::fabs(h(lo, lo - 1)) < eps * s) {
        h(lo, lo - 1) = 0;
        break;
      }
      --lo;
    }
    if (lo == hi) {
      eigenvalues.push_back(h(hi, hi));
      --hi;
      iterations = 0;
    } else if (lo == hi - 1) {
      const double a = h(hi - 1, hi - 1), b = h(hi - 1, hi), c = h(hi, hi - 1), d = h(hi, hi);
      const double p = (a - d) / 2, q = p * p + b * c;
      if (q >= 0) {
        const double z = p + std::copysign(std::sqrt(q), p);
        const double first = d + z;
        eigenvalues.push_back(first);
        eigenvalues.push_back(z != 0 ? d - b * c / z : first);
      } else {
        const double im = std::sqrt(-q);
        eigenvalues.push_back(C(d + p, im));
        eigenvalues.push_back(C(d + p, -im));
      }
      hi -= 2;
      iterations = 0;
    } else {
      if (++iterations > 60) return false;
      double x = h(hi, hi), y = h(hi - 1, hi - 1), w = h(hi, hi - 1) * h(hi - 1, hi);
      if (iterations % 10 == 0) {  // an exceptional shift breaks a cycle
        const double s = std::fabs(h(hi, hi - 1)) + std::fabs(h(hi - 1, hi - 2));
        x = y = x + 0.75 * s;
        w = -0.4375 * s * s;
      }
      francis_step(h, lo, hi, x, y, w);
    }
  }
  return true;
}

}  // namespace

vnl_real_eigensystem::vnl_real_eigensystem(const vnl_matrix<double>& M)
    : Vreal(M.rows(), M.cols(), 0.0), V(M.rows(), M.cols(), C(0)), D(M.rows()) {
  const unsigned n = M.rows();
  if (n == 0 || M.cols() != n) return;
  vnl_matrix<double> h = M;
  reduce_to_hessenberg(h);
  std::vector<C> eigenvalues;
  if (!hessenberg_eigenvalues(h, eigenvalues)) {
    std::cerr << "vnl_real_eigensystem: the QR iteration did not converge\n";
    return;
  }
  // Pairs adjacent, the positive imaginary part first, as EISPACK gives them.
  const double norm = M.operator_one_norm();
  vnl_matrix<C> complex_m(n, n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) complex_m(i, j) = M(i, j);
  for (unsigned k = 0; k < n; ++k) {
    C lambda = eigenvalues[k];
    if (lambda.imag() < 0 && k + 1 < n && eigenvalues[k + 1] == std::conj(lambda)) {
      std::swap(eigenvalues[k], eigenvalues[k + 1]);
      lambda = eigenvalues[k];
    }
    D(k, k) = lambda;
    const vnl_vector<C> v = vnl_algo_detail::inverse_iteration(complex_m, lambda, norm);
    if (lambda.imag() == 0) {
      for (unsigned i = 0; i < n; ++i) {
        V(i, k) = C(v[i].real());
        Vreal(i, k) = v[i].real();
      }
    } else {
      for (unsigned i = 0; i < n; ++i) {
        V(i, k) = v[i];
        V(i, k + 1) = std::conj(v[i]);
        Vreal(i, k) = v[i].real();
        Vreal(i, k + 1) = v[i].imag();
      }
      D(k + 1, k + 1) = std::conj(lambda);
      ++k;
    }
  }
}

}  // inline namespace edgetrack_ports
