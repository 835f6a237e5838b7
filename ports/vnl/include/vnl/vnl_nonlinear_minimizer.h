// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_nonlinear_minimizer.h: the tolerances, counters and return codes
/// shared by the nonlinear minimisers, templated on the scalar. Upstream's defaults
/// (xtol 1e-8, ftol 1e-10, gtol 1e-5, epsfcn 1e-11) are kept, but never below the scalar's
/// epsilon: in fixed point a tolerance under one ulp would round to zero.
#pragma once

#include <limits>

template <class T>
class vnl_nonlinear_minimizer_of {
 public:
  /// MINPACK's info codes, as upstream names them.
  enum ReturnCodes {
    ERROR_FAILURE = -1,
    ERROR_DODGY_INPUT = 0,
    CONVERGED_FTOL = 1,
    CONVERGED_XTOL = 2,
    CONVERGED_XFTOL = 3,
    CONVERGED_GTOL = 4,
    FAILED_TOO_MANY_ITERATIONS = 5,
    TOO_MANY_ITERATIONS = 5,
    FAILED_FTOL_TOO_SMALL = 6,
    FAILED_XTOL_TOO_SMALL = 7,
    FAILED_GTOL_TOO_SMALL = 8,
    FAILED_USER_REQUEST = 9
  };

  vnl_nonlinear_minimizer_of()
      : xtol(at_least_epsilon(kDefaultXtol)),
        ftol(at_least_epsilon(kDefaultFtol)),
        gtol(at_least_epsilon(kDefaultGtol)),
        epsfcn(at_least_epsilon(kDefaultEpsfcn)) {}

  /// Stop when the relative reduction of the sum of squares is below v.
  void set_f_tolerance(T v) { ftol = v; }
  T get_f_tolerance() const { return ftol; }
  /// Stop when the relative change of x (scaled) is below v.
  void set_x_tolerance(T v) { xtol = v; }
  T get_x_tolerance() const { return xtol; }
  /// Stop when the cosine between the residuals and every Jacobian column is below v.
  void set_g_tolerance(T v) { gtol = v; }
  T get_g_tolerance() const { return gtol; }
  void set_max_function_evals(int v) { maxfev = v; }
  int get_max_function_evals() const { return maxfev; }
  /// Relative step of the forward differences: sqrt(max(v, epsilon)).
  void set_epsilon_function(T v) { epsfcn = v; }
  T get_epsilon_function() const { return epsfcn; }
  void set_trace(bool on) { trace = on; }
  bool get_trace() const { return trace; }
  void set_verbose(bool on) { verbose_ = on; }
  bool get_verbose() const { return verbose_; }

  /// RMS of the residuals at the start and at the end of the last minimisation.
  T get_start_error() const { return start_error_; }
  T get_end_error() const { return end_error_; }
  /// Residual evaluations and (for lmder: the same count; for lmdif: progress calls) iterations.
  int get_num_evaluations() const { return num_evaluations_; }
  int get_num_iterations() const { return num_iterations_; }
  ReturnCodes get_failure_code() const { return failure_code_; }

 protected:
  // Upstream's defaults, converted at compile time (no double arithmetic at run time).
  static constexpr T kDefaultXtol = T(1e-8);
  static constexpr T kDefaultFtol = T(1e-10);
  static constexpr T kDefaultGtol = T(1e-5);
  static constexpr T kDefaultEpsfcn = T(1e-11);

  static T at_least_epsilon(T v) {
    const T eps = std::numeric_limits<T>::epsilon();
    return v < eps ? eps : v;
  }

  T xtol;
  T ftol;
  T gtol;
  T epsfcn;
  int maxfev = 2000;
  bool trace = false;
  bool verbose_ = false;
  T start_error_ = T(0);
  T end_error_ = T(0);
  int num_evaluations_ = 0;
  int num_iterations_ = 0;
  ReturnCodes failure_code_ = ERROR_FAILURE;
};
