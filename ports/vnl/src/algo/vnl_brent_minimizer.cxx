// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_brent_minimizer.h"

#include <cmath>
#include <utility>

#include "vnl/algo/vnl_bracket_minimum.h"

inline namespace edgetrack_ports {

namespace {
constexpr double kGoldenSection = 0.3819660112501051;  // (3 - sqrt 5) / 2
constexpr double kAbsoluteTolerance = 1e-12;            // keeps the test meaningful near x = 0
}  // namespace

double vnl_brent_minimizer::f(double x) {
  ++num_evaluations_;
  vnl_vector<double> v(1, x);
  return f_->f(v);
}

double vnl_brent_minimizer::minimize(double ax) {
  double a = ax, b = ax + 1, c = 0, fa = 0, fb = 0, fc = 0;
  vnl_bracket_minimum(*f_, a, b, c, fa, fb, fc);
  return minimize_given_bounds_and_all_f(a, b, c, fa, fb, fc);
}

double vnl_brent_minimizer::minimize_given_bounds(double ax, double bx, double cx) {
  return minimize_given_bounds_and_one_f(ax, bx, cx, f(bx));
}

double vnl_brent_minimizer::minimize_given_bounds_and_one_f(double ax, double bx, double cx, double fb) {
  return minimize_given_bounds_and_all_f(ax, bx, cx, f(ax), fb, f(cx));
}

double vnl_brent_minimizer::minimize_given_bounds_and_all_f(double ax, double bx, double cx, double, double fb,
                                                            double) {
  double lo = std::fmin(ax, cx), hi = std::fmax(ax, cx);
  double x = bx, w = bx, v = bx, fx = fb, fw = fb, fv = fb;
  double step = 0, last_step = 0;
  num_iterations_ = 0;
  for (; num_iterations_ < maxfev; ++num_iterations_) {
    const double mid = (lo + hi) / 2;
    const double tol = xtol * std::fabs(x) + kAbsoluteTolerance, tol2 = 2 * tol;
    if (std::fabs(x - mid) <= tol2 - (hi - lo) / 2) {
      failure_code_ = CONVERGED_XTOL;
      break;
    }
    bool golden = true;
    if (std::fabs(last_step) > tol) {  // try the parabola through x, w, v
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::fabs(q);
      if (std::fabs(p) < std::fabs(q * last_step / 2) && p > q * (lo - x) && p < q * (hi - x)) {
        last_step = step;
        step = p / q;
        const double u = x + step;
        if (u - lo < tol2 || hi - u < tol2) step = mid > x ? tol : -tol;
        golden = false;
      }
    }
    if (golden) {
      last_step = x >= mid ? lo - x : hi - x;
      step = kGoldenSection * last_step;
    }
    const double u = std::fabs(step) >= tol ? x + step : x + (step > 0 ? tol : -tol);
    const double fu = f(u);
    if (fu <= fx) {
      (u >= x ? lo : hi) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? lo : hi) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  if (num_iterations_ >= maxfev) failure_code_ = FAILED_TOO_MANY_ITERATIONS;
  f_at_last_minimum_ = fx;
  return x;
}

}  // inline namespace edgetrack_ports
