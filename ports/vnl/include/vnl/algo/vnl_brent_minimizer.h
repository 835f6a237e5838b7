// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_brent_minimizer.h: Brent's method (golden-section search
/// with parabolic interpolation) for the minimum of a one-variable vnl_cost_function, to within
/// the x tolerance (relative, plus a small absolute part). minimize(x) first brackets a
/// minimum from x with vnl_bracket_minimum.
#pragma once

#ifdef vnl_brent_minimizer_h_
#error "edgetrack's drop-in vnl/algo/vnl_brent_minimizer.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_nonlinear_minimizer.h"

inline namespace edgetrack_ports {

class vnl_brent_minimizer : public vnl_nonlinear_minimizer_of<double> {
 public:
  explicit vnl_brent_minimizer(vnl_cost_function& functor) : f_(&functor) {}
  ~vnl_brent_minimizer() = default;

  /// The minimiser found from the start ax.
  double minimize(double ax);
  /// f at the last minimum found.
  double f_at_last_minimum() const { return f_at_last_minimum_; }
  /// The minimiser inside the bracket ax < bx < cx (or reversed) with f(bx) below both ends.
  double minimize_given_bounds(double ax, double bx, double cx);
  double minimize_given_bounds_and_one_f(double ax, double bx, double cx, double fb);
  double minimize_given_bounds_and_all_f(double ax, double bx, double cx, double fa, double fb, double fc);

 private:
  double f(double x);

  vnl_cost_function* f_;
  double f_at_last_minimum_ = 0;
};

}  // inline namespace edgetrack_ports
