// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_amoeba.h: Nelder-Mead downhill simplex minimisation of a
/// vnl_cost_function, without derivatives. The start simplex is x and, per coordinate, x with
/// that coordinate scaled by 1 + relative_diameter (or set to zero_term_delta when it is near
/// zero), or x plus dx[i]. It stops when the simplex is smaller than X_tolerance in every
/// coordinate and its values spread less than F_tolerance, or after maxiter evaluations.
/// Upstream's process-wide `default_verbose` is not provided (no shared mutable state here).
#pragma once

#ifdef vnl_amoeba_h_
#error "edgetrack's drop-in vnl/algo/vnl_amoeba.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_cost_function;
class vnl_least_squares_function;

class vnl_amoeba {
 public:
  int verbose = 0;
  int maxiter;
  double X_tolerance = 1e-8;
  double F_tolerance = 1e-4;
  double relative_diameter = 0.05;
  double zero_term_delta = 0.00025;

  explicit vnl_amoeba(vnl_cost_function& f);

  void set_max_iterations(int n) { maxiter = n; }
  void set_x_tolerance(double tol) { X_tolerance = tol; }
  void set_f_tolerance(double tol) { F_tolerance = tol; }
  void set_relative_diameter(double r) { relative_diameter = r; }
  void set_zero_term_delta(double d) { zero_term_delta = d; }

  /// Moves x to the minimum found from the relative start simplex.
  void minimize(vnl_vector<double>& x);
  /// The same from the simplex x, x + dx[i] e_i.
  void minimize(vnl_vector<double>& x, const vnl_vector<double>& dx);
  double get_end_error() const { return end_error_; }
  int get_num_evaluations() const { return num_evaluations_; }

  static void minimize(vnl_cost_function& f, vnl_vector<double>& x);
  static void minimize(vnl_cost_function& f, vnl_vector<double>& x, const vnl_vector<double>& dx);
  /// With delta != 0 as the relative diameter.
  static void minimize(vnl_cost_function& f, vnl_vector<double>& x, double delta);
  /// Minimises the sum of squares of f's residuals.
  static void minimize(vnl_least_squares_function& f, vnl_vector<double>& x);

 protected:
  vnl_cost_function* fptr;
  double end_error_ = 0;
  int num_evaluations_ = 0;
};

/// A corner of the simplex: a point and the cost there.
struct vnl_amoeba_SimplexCorner {
  vnl_vector<double> v;
  double fv = 0;
  explicit vnl_amoeba_SimplexCorner(int n = 0) : v(n) {}
  /// The sign of s1.fv - s2.fv.
  static int compare(const vnl_amoeba_SimplexCorner& s1, const vnl_amoeba_SimplexCorner& s2) {
    return (s1.fv > s2.fv) - (s1.fv < s2.fv);
  }
};

}  // inline namespace edgetrack_ports
