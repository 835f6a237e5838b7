// SPDX-License-Identifier: BSD-3-Clause
/// The line search of vnl_conjugate_gradient and vnl_lbfgs (upstream has one inside each netlib
/// routine): along a descent direction d from x, a step a meeting the strong Wolfe conditions
///   f(x + a d) <= f(x) + c1 a g.d   and   |g(x + a d).d| <= c2 |g.d|,
/// found by doubling the step until the minimum is bracketed, then shrinking the bracket
/// (Nocedal and Wright, algorithms 3.5 and 3.6) with safeguarded quadratic interpolation.
#pragma once

#include <cmath>

#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

namespace vnl_algo_detail {

/// A point on the line: the step, x there, f and g there, and the slope g.d.
struct LinePoint {
  double step = 0;
  double f = 0;
  double slope = 0;
  vnl_vector<double> x, g;
};

/// An evaluator for wolfe_line_search: f and its gradient from `f`, each value passed to
/// `report` (the minimiser's report_eval).
template <class Report>
auto cost_evaluator(vnl_cost_function& f, Report report) {
  return [&f, report](const vnl_vector<double>& at, vnl_vector<double>& g) {
    double value = 0;
    f.compute(at, &value, &g);
    report(value);
    return value;
  };
}

/// The line point at x, evaluated.
template <class Evaluate>
LinePoint point_at(Evaluate& evaluate, const vnl_vector<double>& x) {
  LinePoint p;
  p.x = x;
  p.g.set_size(x.size());
  p.f = evaluate(x, p.g);
  return p;
}

/// `evaluate(x, g)` returns f(x) and writes the gradient to g; `start` holds x, f, g and the
/// slope there (its step is ignored). On success `out` is the accepted point; on failure (no
/// sufficient decrease within the evaluation budget) `out` is the best point seen, which is
/// the start when nothing was lower.
template <class Evaluate>
bool wolfe_line_search(Evaluate&& evaluate, const LinePoint& start, const vnl_vector<double>& d, double first_step,
                       double c1, double c2, LinePoint& out) {
  constexpr int kMaxEvaluations = 40;
  const double slope0 = start.slope;
  if (!(slope0 < 0)) {
    out = start;
    return false;
  }
  int evaluations = 0;
  auto at = [&](double step) {
    LinePoint p;
    p.step = step;
    p.x = start.x + step * d;
    p.g.set_size(d.size());
    p.f = evaluate(p.x, p.g);
    p.slope = dot_product(p.g, d);
    ++evaluations;
    return p;
  };
  auto sufficient = [&](const LinePoint& p) { return p.f <= start.f + c1 * p.step * slope0; };
  auto curvature = [&](const LinePoint& p) { return std::fabs(p.slope) <= -c2 * slope0; };
  LinePoint origin = start;
  origin.step = 0;
  LinePoint best = origin;
  auto keep_best = [&](const LinePoint& p) {
    if (p.f < best.f) best = p;
  };

  // Bracketing: lo is the best point meeting sufficient decrease, hi a point beyond the minimum.
  LinePoint lo = origin, hi;
  bool bracketed = false;
  for (double step = first_step; evaluations < kMaxEvaluations; step *= 2) {
    LinePoint p = at(step);
    keep_best(p);
    if (!std::isfinite(p.f)) break;
    if (!sufficient(p) || (evaluations > 1 && p.f >= lo.f)) {
      hi = p;
      bracketed = true;
      break;
    }
    if (curvature(p)) {
      out = p;
      return true;
    }
    if (p.slope >= 0) {
      hi = lo;
      lo = p;
      bracketed = true;
      break;
    }
    lo = p;
  }
  // Zoom: the minimum lies between lo (sufficient decrease, lowest f) and hi.
  while (bracketed && evaluations < kMaxEvaluations) {
    const double width = hi.step - lo.step;
    // Minimum of the quadratic through f(lo), its slope and f(hi), kept inside the bracket.
    const double denominator = 2 * (hi.f - lo.f - lo.slope * width);
    double step = denominator > 0 ? lo.step - lo.slope * width * width / denominator : lo.step + width / 2;
    const double low = std::fmin(lo.step, hi.step) + 0.1 * std::fabs(width);
    const double high = std::fmax(lo.step, hi.step) - 0.1 * std::fabs(width);
    step = std::fmin(std::fmax(step, low), high);
    LinePoint p = at(step);
    keep_best(p);
    if (!sufficient(p) || p.f >= lo.f) {
      hi = p;
    } else {
      if (curvature(p)) {
        out = p;
        return true;
      }
      if (p.slope * (hi.step - lo.step) >= 0) hi = lo;
      lo = p;
    }
    if (std::fabs(hi.step - lo.step) <= 1e-16 * std::fmax(1.0, std::fabs(lo.step))) break;
  }
  out = best;
  return best.f < start.f && sufficient(best);
}

}  // namespace vnl_algo_detail

}  // inline namespace edgetrack_ports
