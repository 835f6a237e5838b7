// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_simpson_integral.h"

inline namespace edgetrack_ports {

double vnl_simpson_integral::integral(vnl_integrant_fnct* f, double a, double b, long n) {
  set_fnct(f);
  if (n < 2) n = 2;
  if (n % 2) ++n;
  const double h = (b - a) / n;
  double total = pfnct_->f_(a) + pfnct_->f_(b);
  for (long i = 1; i < n; ++i) total += (i % 2 ? 4 : 2) * pfnct_->f_(a + i * h);
  return total * h / 3;
}

}  // inline namespace edgetrack_ports
