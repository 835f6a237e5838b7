// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_powell.h"

#include <cmath>

#include "vnl/algo/vnl_bracket_minimum.h"
#include "vnl/algo/vnl_brent_minimizer.h"
#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

/// f along the line origin + lambda * direction, as a cost of one unknown.
class vnl_powell_1dfun : public vnl_cost_function {
 public:
  vnl_powell_1dfun(unsigned n, vnl_cost_function* f, vnl_powell* powell)
      : vnl_cost_function(1), powell_(powell), f_(f), origin_(n), direction_(n), point_(n) {}
  void set_line(const vnl_vector<double>& origin, const vnl_vector<double>& direction) {
    origin_ = origin;
    direction_ = direction;
  }
  double f(const vnl_vector<double>& lambda) override {
    point_at(lambda[0], point_);
    const double e = f_->f(point_);
    powell_->pub_report_eval(e);
    return e;
  }
  void point_at(double lambda, vnl_vector<double>& out) const {
    for (unsigned i = 0; i < out.size(); ++i) out[i] = origin_[i] + lambda * direction_[i];
  }

  /// Minimises along the line from step `first_step`; moves x to the minimum, returns f there.
  double minimize_along(vnl_vector<double>& x, double first_step, double xtol) {
    double a = 0, b = first_step, c = 0, fa = 0, fb = 0, fc = 0;
    vnl_bracket_minimum(*this, a, b, c, fa, fb, fc);
    vnl_brent_minimizer brent(*this);
    brent.set_x_tolerance(xtol);
    const double lambda = brent.minimize_given_bounds(a, b, c);
    point_at(lambda, x);
    return brent.f_at_last_minimum();
  }

 private:
  vnl_powell* powell_;
  vnl_cost_function* f_;
  vnl_vector<double> origin_, direction_, point_;
};

vnl_nonlinear_minimizer::ReturnCodes vnl_powell::minimize(vnl_vector<double>& p) {
  const unsigned n = p.size();
  vnl_powell_1dfun line(n, functor_, this);
  vnl_matrix<double> directions(n, n);
  directions.set_identity();
  vnl_vector<double> direction(n), extrapolated(n), start = p;
  double f_now = functor_->f(p);
  report_eval(f_now);
  while (num_iterations_ < maxfev) {
    const double f_start = f_now;
    unsigned biggest = 0;
    double biggest_drop = 0;
    for (unsigned i = 0; i < n; ++i) {
      direction = directions.get_column(i);
      const double f_before = f_now;
      line.set_line(p, direction);
      f_now = line.minimize_along(p, initial_step_, linmin_xtol_);
      if (std::fabs(f_before - f_now) > biggest_drop) biggest_drop = std::fabs(f_before - f_now), biggest = i;
    }
    if (2 * std::fabs(f_start - f_now) <= ftol * (std::fabs(f_start) + std::fabs(f_now))) return CONVERGED_FTOL;
    // The net step of this iteration, and f one more such step ahead.
    direction = p - start;
    extrapolated = p + direction;
    start = p;
    const double f_extrapolated = functor_->f(extrapolated);
    report_eval(f_extrapolated);
    if (f_extrapolated < f_start) {
      const double a = f_start - f_now - biggest_drop, b = f_start - f_extrapolated;
      const double t = 2 * (f_start - 2 * f_now + f_extrapolated) * a * a - biggest_drop * b * b;
      if (t < 0) {
        line.set_line(p, direction);
        f_now = line.minimize_along(p, 1.0, linmin_xtol_);
        directions.set_column(biggest, directions.get_column(n - 1));
        directions.set_column(n - 1, direction);
      }
    }
    if (report_iter()) return FAILED_USER_REQUEST;
  }
  return TOO_MANY_ITERATIONS;
}

}  // inline namespace edgetrack_ports
