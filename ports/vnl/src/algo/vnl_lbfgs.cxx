// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_lbfgs.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>
#include <vector>

#include "wolfe_line_search.h"

inline namespace edgetrack_ports {

namespace {

constexpr double kSufficientDecrease = 1e-4;

/// One remembered step: s = x' - x, y = g' - g, rho = 1 / y.s.
struct Correction {
  vnl_vector<double> s, y;
  double rho;
};

/// -H g by the two-loop recursion, H0 = (s.y / y.y) I from the newest pair.
vnl_vector<double> descent_direction(const vnl_vector<double>& g, const std::deque<Correction>& pairs) {
  vnl_vector<double> q = g;
  std::vector<double> alpha(pairs.size());
  for (size_t k = pairs.size(); k-- > 0;) {
    alpha[k] = pairs[k].rho * dot_product(pairs[k].s, q);
    q -= alpha[k] * pairs[k].y;
  }
  if (!pairs.empty()) {
    const Correction& newest = pairs.back();
    q *= 1 / (newest.rho * dot_product(newest.y, newest.y));
  }
  for (size_t k = 0; k < pairs.size(); ++k) {
    const double beta = pairs[k].rho * dot_product(pairs[k].y, q);
    q += (alpha[k] - beta) * pairs[k].s;
  }
  return -q;
}

}  // namespace

bool vnl_lbfgs::minimize(vnl_vector<double>& x) {
  reset();
  auto evaluate = vnl_algo_detail::cost_evaluator(*f_, [this](double value) { report_eval(value); });
  vnl_algo_detail::LinePoint here = vnl_algo_detail::point_at(evaluate, x);
  std::deque<Correction> pairs;
  bool ok = false;
  while (true) {
    if (here.g.two_norm() <= gtol * std::max(1.0, here.x.two_norm())) {
      failure_code_ = CONVERGED_GTOL;
      ok = true;
      break;
    }
    if (num_evaluations_ > maxfev) {
      failure_code_ = TOO_MANY_ITERATIONS;
      break;
    }
    vnl_vector<double> d = descent_direction(here.g, pairs);
    here.slope = dot_product(here.g, d);
    if (!(here.slope < 0)) {
      pairs.clear();
      d = -here.g;
      here.slope = dot_product(here.g, d);
    }
    const double first = pairs.empty() ? default_step_length / here.g.two_norm() : default_step_length;
    vnl_algo_detail::LinePoint next;
    if (!vnl_algo_detail::wolfe_line_search(evaluate, here, d, first, kSufficientDecrease, line_search_accuracy,
                                            next)) {
      failure_code_ = ABNORMAL_TERMINATION_IN_LNSRCH;
      if (next.f < here.f) here = next;
      break;
    }
    Correction c{next.x - here.x, next.g - here.g, 0};
    const double sy = dot_product(c.s, c.y);
    if (sy > 0) {
      c.rho = 1 / sy;
      pairs.push_back(std::move(c));
      if (static_cast<int>(pairs.size()) > memory) pairs.pop_front();
    }
    here = next;
    if (report_iter()) {
      failure_code_ = FAILED_USER_REQUEST;
      break;
    }
  }
  x = here.x;
  end_error_ = here.f;
  return ok;
}

}  // inline namespace edgetrack_ports
