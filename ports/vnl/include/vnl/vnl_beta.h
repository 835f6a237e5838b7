// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_beta.h: the beta function B(x, y) = Gamma(x) Gamma(y) /
/// Gamma(x + y) and its logarithm, computed in double from vnl_log_gamma.
#pragma once

#include <cmath>

#include "vnl/vnl_gamma.h"

template <class T>
inline double vnl_log_beta(T x, T y) {
  const double a = static_cast<double>(x), b = static_cast<double>(y);
  return vnl_log_gamma(a) + vnl_log_gamma(b) - vnl_log_gamma(a + b);
}
template <class T>
inline double vnl_beta(T x, T y) {
  return std::exp(vnl_log_beta(x, y));
}
