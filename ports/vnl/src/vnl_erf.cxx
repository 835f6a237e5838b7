// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_erf.h"

#include <cmath>

inline namespace edgetrack_ports {

double vnl_erfc(double x) { return std::erfc(x); }

double vnl_scaled_erfc(double x) {
  if (x < 25) return std::exp(x * x) * std::erfc(x);
  // 1/(x sqrt(pi)) sum_k (-1)^k (2k-1)!! f^k, f = 1/(2x^2): seven terms; at x >= 25 the
  // next is below 3e-17 relative.
  const double f = 1 / (2 * x * x);
  const double series = 1 - f * (1 - 3 * f * (1 - 5 * f * (1 - 7 * f * (1 - 9 * f * (1 - 11 * f)))));
  return series / (x * 1.7724538509055160273);
}

}  // inline namespace edgetrack_ports
