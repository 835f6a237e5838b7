// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_beta.h: the beta function B(x, y) = Gamma(x) Gamma(y) /
/// Gamma(x + y) and its logarithm, computed in double from vnl_log_gamma.
#pragma once

#ifdef vnl_beta_h_
#error "edgetrack's drop-in vnl/vnl_beta.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>

#include "vnl/vnl_gamma.h"

inline namespace edgetrack_ports {

template <class T>
inline double vnl_log_beta(T x, T y) {
  const double a = static_cast<double>(x), b = static_cast<double>(y);
  return vnl_log_gamma(a) + vnl_log_gamma(b) - vnl_log_gamma(a + b);
}
template <class T>
inline double vnl_beta(T x, T y) {
  return std::exp(vnl_log_beta(x, y));
}

}  // inline namespace edgetrack_ports
