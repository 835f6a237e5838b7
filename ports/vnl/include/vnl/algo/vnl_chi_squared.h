// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_chi_squared.h: the chi-squared distribution's CDF (in
/// closed form as P(dof/2, chisq/2), where upstream calls netlib's dchscdf) and the
/// chi-squared statistics between two histograms: sum (a-b)^2/a, sum (a-b)^2/b and
/// sum (a-b)^2/(a+b), optionally on normalised histograms. Computed in double, as upstream.
#pragma once

#ifdef vnl_chi_squared_h_
#error "edgetrack's drop-in vnl/algo/vnl_chi_squared.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_gamma.h"

inline namespace edgetrack_ports {

template <class T>
double vnl_chi_squared_cumulative(T chisq, long dof) {
  return vnl_gamma_p(0.5 * static_cast<double>(dof), 0.5 * static_cast<double>(chisq));
}

namespace vnl_chi_squared_detail {
/// sum over bins of (a - b)^2 / weight(a, b), skipping bins whose weight is zero.
template <class T, class Weight>
double statistic(const T* A, const T* B, int n, bool normalize, Weight weight) {
  double sum_a = 1, sum_b = 1;
  if (normalize) {
    sum_a = sum_b = 0;
    for (int i = 0; i < n; ++i) sum_a += static_cast<double>(A[i]), sum_b += static_cast<double>(B[i]);
  }
  double total = 0;
  for (int i = 0; i < n; ++i) {
    const double a = static_cast<double>(A[i]) / sum_a, b = static_cast<double>(B[i]) / sum_b;
    const double w = weight(a, b);
    if (w != 0) total += (a - b) * (a - b) / w;
  }
  return total;
}
}  // namespace vnl_chi_squared_detail

template <class T>
double vnl_chi_squared_statistic_1(const T* A, const T* B, int n, bool normalize) {
  return vnl_chi_squared_detail::statistic(A, B, n, normalize, [](double a, double) { return a; });
}
template <class T>
double vnl_chi_squared_statistic_2(const T* A, const T* B, int n, bool normalize) {
  return vnl_chi_squared_statistic_1(B, A, n, normalize);
}
template <class T>
double vnl_chi_squared_statistic_12(const T* A, const T* B, int n, bool normalize) {
  return vnl_chi_squared_detail::statistic(A, B, n, normalize, [](double a, double b) { return a + b; });
}

}  // inline namespace edgetrack_ports
