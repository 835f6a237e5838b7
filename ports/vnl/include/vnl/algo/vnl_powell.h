// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_powell.h: Powell's direction-set minimisation of a
/// vnl_cost_function without derivatives. Each iteration minimises along every direction in
/// turn (bracketed from initial_step, then Brent to linmin_xtol), then replaces the direction
/// of largest decrease by the iteration's net step when that helps. It stops when an
/// iteration lowers f by less than ftol relative to |f| (CONVERGED_FTOL), after maxfev
/// iterations (TOO_MANY_ITERATIONS), or when report_iter asks to (FAILED_USER_REQUEST).
#pragma once

#ifdef vnl_powell_h_
#error "edgetrack's drop-in vnl/algo/vnl_powell.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_nonlinear_minimizer.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_powell : public vnl_nonlinear_minimizer {
 public:
  explicit vnl_powell(vnl_cost_function* functor) : functor_(functor) {}

  /// Moves x to the minimum found; returns why it stopped.
  ReturnCodes minimize(vnl_vector<double>& x);
  /// Tolerance of each line minimisation (default 1e-4).
  void set_linmin_xtol(double tol) { linmin_xtol_ = tol; }
  /// First step of each bracketing along a direction (default 1).
  void set_initial_step(double step) { initial_step_ = step; }

 protected:
  friend class vnl_powell_1dfun;
  void pub_report_eval(double e) { report_eval(e); }

  vnl_cost_function* functor_;
  double linmin_xtol_ = 1e-4;
  double initial_step_ = 1.0;
};

}  // inline namespace edgetrack_ports
