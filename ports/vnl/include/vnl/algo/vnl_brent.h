// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_brent.h: upstream's older interface to Brent's
/// one-dimensional minimiser, kept over vnl_brent_minimizer (which new code should use).
/// minimize_given_bounds* return f at the minimum and write the minimiser to *xmin;
/// bracket_minimum returns a bracket with ax > bx > cx or the reverse, f(bx) below both ends.
#pragma once

#ifdef vnl_brent_h_
#error "edgetrack's drop-in vnl/algo/vnl_brent.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/algo/vnl_brent_minimizer.h"
#include "vnl/vnl_cost_function.h"

inline namespace edgetrack_ports {

class vnl_brent : public vnl_brent_minimizer {
 public:
  explicit vnl_brent(vnl_cost_function* functor) : vnl_brent_minimizer(*functor), functor_(functor) {}
  ~vnl_brent() = default;

  /// The minimiser found from x, bracketing from x - 1 and x + 1; ftol is the x tolerance.
  double minimize(double x);
  double minimize_given_bounds(double ax, double bx, double cx, double tol, double* xmin);
  double minimize_given_bounds_and_1st_f(double ax, double bx, double fb, double cx, double tol, double* xmin);
  void bracket_minimum(double* ax, double* bx, double* cx, double* fa, double* fb, double* fc);
  void bracket_minimum(double* ax, double* bx, double* cx);

 private:
  vnl_cost_function* functor_;
};

}  // inline namespace edgetrack_ports
