// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_conjugate_gradient.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "wolfe_line_search.h"

inline namespace edgetrack_ports {

namespace {
constexpr double kSufficientDecrease = 1e-4;  // c1, as usual
constexpr double kCurvature = 0.1;            // c2: an accurate search, as conjugacy needs
}  // namespace

void vnl_conjugate_gradient::init(vnl_cost_function& f) {
  f_ = &f;
  num_iterations_ = 0;
  num_evaluations_ = 0;
  start_error_ = 0;
  end_error_ = 0;
}

bool vnl_conjugate_gradient::minimize(vnl_vector<double>& x) {
  reset();
  final_step_size_ = 0;
  auto evaluate = vnl_algo_detail::cost_evaluator(*f_, [this](double value) { report_eval(value); });
  vnl_algo_detail::LinePoint here = vnl_algo_detail::point_at(evaluate, x);
  vnl_vector<double> d = -here.g;
  double last_step = 0, last_slope = 0;
  failure_code_ = TOO_MANY_ITERATIONS;
  while (true) {
    if (here.g.inf_norm() <= gtol) {
      failure_code_ = CONVERGED_GTOL;
      break;
    }
    if (num_iterations_ >= maxfev) break;
    here.slope = dot_product(here.g, d);
    if (!(here.slope < 0)) {  // lost conjugacy: restart along the steepest descent
      d = -here.g;
      here.slope = dot_product(here.g, d);
    }
    // The first step is 1 / |g|; later ones expect the same decrease as the last iteration.
    const double first = last_step > 0 ? std::min(1.0, 1.01 * last_step * last_slope / here.slope)
                                       : 1 / std::max(here.g.two_norm(), 1e-300);
    vnl_algo_detail::LinePoint next;
    if (!vnl_algo_detail::wolfe_line_search(evaluate, here, d, first > 0 ? first : 1.0, kSufficientDecrease,
                                            kCurvature, next)) {
      failure_code_ = ERROR_DODGY_INPUT;  // upstream: netlib cg's error codes
      if (next.f < here.f) here = next;
      break;
    }
    last_step = next.step;
    last_slope = here.slope;
    const double beta = std::max(0.0, dot_product(next.g, next.g - here.g) / dot_product(here.g, here.g));
    d = beta * d - next.g;
    here = next;
    final_step_size_ = last_step;
    if (report_iter()) {
      failure_code_ = FAILED_USER_REQUEST;
      break;
    }
  }
  x = here.x;
  end_error_ = here.f;
  return failure_code_ == CONVERGED_GTOL;
}

void vnl_conjugate_gradient::diagnose_outcome() const { diagnose_outcome(std::cout); }

void vnl_conjugate_gradient::diagnose_outcome(std::ostream& s) const {
  s << "vnl_conjugate_gradient: " << (failure_code_ == CONVERGED_GTOL ? "converged" : "did not converge") << " after "
    << num_iterations_ << " iterations, " << num_evaluations_ << " evaluations, final step " << final_step_size_
    << "; start value " << start_error_ << ", end value " << end_error_ << '\n';
}

}  // inline namespace edgetrack_ports
