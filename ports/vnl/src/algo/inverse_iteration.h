// SPDX-License-Identifier: BSD-3-Clause
/// The eigenvector step of vnl_real_eigensystem and vnl_complex_eigensystem: given an
/// eigenvalue lambda of a (complex) square matrix, a unit eigenvector by two steps of inverse
/// iteration on A - lambda I, shifted one part in 1e10 off lambda so that the factorisation
/// exists yet stays nearly singular. The largest component comes out real and positive.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

namespace vnl_algo_detail {

inline vnl_vector<std::complex<double>> inverse_iteration(const vnl_matrix<std::complex<double>>& a,
                                                          std::complex<double> lambda, double norm) {
  using C = std::complex<double>;
  const unsigned n = a.rows();
  const double scale = std::max(norm, 1e-300);
  const C shifted = lambda + C(1e-10 * scale, 0);
  vnl_matrix<C> m = a;
  for (unsigned i = 0; i < n; ++i) m(i, i) -= shifted;
  std::vector<unsigned> pivot(n);
  for (unsigned k = 0; k < n; ++k) {  // LU with partial pivoting, in place
    unsigned best = k;
    for (unsigned i = k + 1; i < n; ++i)
      if (std::abs(m(i, k)) > std::abs(m(best, k))) best = i;
    pivot[k] = best;
    if (best != k)
      for (unsigned j = 0; j < n; ++j) std::swap(m(k, j), m(best, j));
    if (m(k, k) == C(0)) m(k, k) = C(std::numeric_limits<double>::epsilon() * scale);
    for (unsigned i = k + 1; i < n; ++i) {
      m(i, k) /= m(k, k);
      for (unsigned j = k + 1; j < n; ++j) m(i, j) -= m(i, k) * m(k, j);
    }
  }
  vnl_vector<C> x(n, C(1));
  for (int pass = 0; pass < 2; ++pass) {
    for (unsigned k = 0; k < n; ++k) std::swap(x[k], x[pivot[k]]);
    for (unsigned i = 0; i < n; ++i)
      for (unsigned k = 0; k < i; ++k) x[i] -= m(i, k) * x[k];
    for (unsigned i = n; i-- > 0;) {
      for (unsigned k = i + 1; k < n; ++k) x[i] -= m(i, k) * x[k];
      x[i] /= m(i, i);
    }
    unsigned big = 0;
    for (unsigned i = 1; i < n; ++i)
      if (std::abs(x[i]) > std::abs(x[big])) big = i;
    const C phase = x[big] / std::abs(x[big]);
    double length = 0;
    for (unsigned i = 0; i < n; ++i) length += std::norm(x[i]);
    for (unsigned i = 0; i < n; ++i) x[i] /= phase * std::sqrt(length);
  }
  return x;
}

}  // namespace vnl_algo_detail

}  // inline namespace edgetrack_ports
