// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_least_squares_cost_function.h: a vnl_least_squares_function
/// seen as a vnl_cost_function, f(x) = |residuals(x)|^2 with gradient 2 J^T residuals (left
/// unchanged when the function has no Jacobian, as upstream), for the cost-function
/// minimisers. The cost side is double as upstream; the residuals are computed on `real`
/// (this port's vnl_least_squares_function) and summed in double.
#pragma once

#include "real/real.h"
#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_least_squares_function.h"

class vnl_least_squares_cost_function : public vnl_cost_function {
 public:
  vnl_least_squares_cost_function(vnl_least_squares_function* f);  // NOLINT(google-explicit-constructor): upstream's
  double f(const vnl_vector<double>& x) override;
  void gradf(const vnl_vector<double>& x, vnl_vector<double>& gradient) override;

 protected:
  vnl_vector<real> storage_;
  vnl_matrix<real> jacobian_;
  vnl_least_squares_function* f_;

 private:
  /// Fills storage_ with the residuals at x; returns x on real.
  vnl_vector<real> residuals_at(const vnl_vector<double>& x);
};
