// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_fit_parabola.h: the parabola through (xa, fa), (xb, fb),
/// (xc, fc) has its extremum at xb + p / q (q == 0 when the points are collinear).
#pragma once

#ifdef vnl_fit_parabola_h_
#error "edgetrack's drop-in vnl/algo/vnl_fit_parabola.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

inline void vnl_fit_parabola(double xa, double xb, double xc, double fa, double fb, double fc, double& p, double& q) {
  const double x1 = xa - xb, f1 = fa - fb;
  const double x2 = xc - xb, f2 = fc - fb;
  p = x2 * x2 * f1 - x1 * x1 * f2;
  q = 2 * (x2 * f1 - x1 * f2);
}

}  // inline namespace edgetrack_ports
