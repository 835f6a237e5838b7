// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_bessel.h"

#include <cmath>

inline namespace edgetrack_ports {

double vnl_bessel(unsigned n, double x) {
  const double j = std::cyl_bessel_j(static_cast<double>(n), std::fabs(x));
  return (x < 0 && n % 2 == 1) ? -j : j;
}

double vnl_bessel0(double x) { return vnl_bessel(0, x); }

void vnl_bessel(unsigned n_max, double x, vnl_vector<double>& J) {
  J.set_size(n_max + 1);
  for (unsigned i = 0; i <= n_max; ++i) J[i] = vnl_bessel(i, x);
}

}  // inline namespace edgetrack_ports
