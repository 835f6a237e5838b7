// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_lbfgs.h: limited-memory BFGS minimisation of a
/// vnl_cost_function with its gradient (upstream: Nocedal's netlib lbfgs; ours: the same
/// two-loop update over the last `memory` steps and a strong-Wolfe line search with
/// c2 = line_search_accuracy). It succeeds when |g| <= gtol max(1, |x|); it fails when the line
/// search finds no lower point or after maxfev evaluations. x is the best point seen.
#pragma once

#ifdef vnl_lbfgs_h_
#error "edgetrack's drop-in vnl/algo/vnl_lbfgs.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_nonlinear_minimizer.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_lbfgs : public vnl_nonlinear_minimizer {
 public:
  vnl_lbfgs() = default;
  explicit vnl_lbfgs(vnl_cost_function& f) : f_(&f) {}

  bool minimize(vnl_vector<double>& x);

  /// Steps remembered for the inverse-Hessian estimate (default 5).
  int memory = 5;
  /// Curvature constant of the line search, in (0, 1): 0.9 is loose, 0.1 accurate.
  double line_search_accuracy = 0.9;
  /// The first trial step of each line search after the first iteration (the first is 1 / |g|).
  double default_step_length = 1.0;

 private:
  vnl_cost_function* f_ = nullptr;
};

}  // inline namespace edgetrack_ports
