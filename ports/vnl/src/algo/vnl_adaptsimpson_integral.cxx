// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_adaptsimpson_integral.h"

#include <cmath>

inline namespace edgetrack_ports {

double vnl_adaptsimpson_integral::integral(vnl_integrant_fnct* f, double a, double b, double accuracy) {
  set_fnct(f);
  const double fa = f->f_(a), fb = f->f_(b), fm = f->f_((a + b) / 2);
  const double whole = (b - a) / 6 * (fa + 4 * fm + fb);
  return adaptivesimpson(a, b, fa, fm, fb, whole, accuracy, 0);
}

double vnl_adaptsimpson_integral::adaptivesimpson(double a, double b, double fa, double fm, double fb, double whole,
                                                  double eps, int level) {
  const double m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
  const double flm = pfnct_->f_(lm), frm = pfnct_->f_(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  const double difference = left + right - whole;
  if (level >= depth_ || std::fabs(difference) <= 15 * eps) return left + right + difference / 15;
  return adaptivesimpson(a, m, fa, flm, fm, left, eps / 2, level + 1) +
         adaptivesimpson(m, b, fm, frm, fb, right, eps / 2, level + 1);
}

}  // inline namespace edgetrack_ports
