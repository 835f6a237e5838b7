// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_conjugate_gradient.h: nonlinear conjugate-gradient
/// minimisation of a vnl_cost_function with its gradient. Ours: Polak-Ribiere directions
/// (restarted along -g when they stop descending) and a strong-Wolfe line search (upstream:
/// netlib's cg). It succeeds when the largest gradient component is at most gtol (default
/// 1e-5) within maxfev iterations, and fails when no step lowers f along a descent direction.
#pragma once

#ifdef vnl_conjugate_gradient_h_
#error "edgetrack's drop-in vnl/algo/vnl_conjugate_gradient.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_nonlinear_minimizer.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_conjugate_gradient : public vnl_nonlinear_minimizer {
 public:
  vnl_conjugate_gradient(vnl_cost_function& f) { init(f); }  // NOLINT: implicit as upstream
  vnl_conjugate_gradient(vnl_cost_function& f, vnl_vector<double>& x) {
    init(f);
    minimize(x);
  }
  void init(vnl_cost_function& f);
  ~vnl_conjugate_gradient() override = default;

  /// Writes the outcome, the counts and the start and end values.
  void diagnose_outcome(std::ostream& s) const;
  void diagnose_outcome() const;
  /// Moves x to the minimum found; true on convergence.
  bool minimize(vnl_vector<double>& x);

 protected:
  vnl_cost_function* f_ = nullptr;
  double final_step_size_ = 0;
};

}  // inline namespace edgetrack_ports
