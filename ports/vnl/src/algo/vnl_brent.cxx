// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_brent.h"

#include "vnl/algo/vnl_bracket_minimum.h"

inline namespace edgetrack_ports {

double vnl_brent::minimize_given_bounds(double ax, double bx, double cx, double tol, double* xmin) {
  set_x_tolerance(tol);
  *xmin = vnl_brent_minimizer::minimize_given_bounds(ax, bx, cx);
  return f_at_last_minimum();
}

double vnl_brent::minimize_given_bounds_and_1st_f(double ax, double bx, double fb, double cx, double tol,
                                                  double* xmin) {
  set_x_tolerance(tol);
  *xmin = minimize_given_bounds_and_one_f(ax, bx, cx, fb);
  return f_at_last_minimum();
}

void vnl_brent::bracket_minimum(double* ax, double* bx, double* cx, double* fa, double* fb, double* fc) {
  // vnl_bracket_minimum starts from its first two points; upstream passes them as (cx, bx).
  vnl_bracket_minimum(*functor_, *cx, *bx, *ax, *fc, *fb, *fa);
}

void vnl_brent::bracket_minimum(double* ax, double* bx, double* cx) {
  double fa = 0, fb = 0, fc = 0;
  bracket_minimum(ax, bx, cx, &fa, &fb, &fc);
}

double vnl_brent::minimize(double x) {
  double ax = x - 1, bx = x + 1, cx = 0, fa = 0, fb = 0, fc = 0;
  bracket_minimum(&ax, &bx, &cx, &fa, &fb, &fc);
  minimize_given_bounds(cx, bx, ax, ftol, &x);
  return x;
}

}  // inline namespace edgetrack_ports
