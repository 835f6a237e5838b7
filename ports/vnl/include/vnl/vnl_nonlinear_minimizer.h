// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_nonlinear_minimizer.h: the tolerances, counters and return codes
/// shared by the nonlinear minimisers, templated on the scalar as vnl_nonlinear_minimizer_of<T>.
/// `vnl_nonlinear_minimizer` is upstream's class, on double in every build. Upstream's defaults
/// (xtol 1e-8, ftol 1e-10, gtol 1e-5, epsfcn 1e-11) are kept, but never below the scalar's
/// epsilon: in fixed point a tolerance under one ulp would round to zero.
#pragma once

#ifdef vnl_nonlinear_minimizer_h_
#error "edgetrack's drop-in vnl/vnl_nonlinear_minimizer.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>
#include <limits>
#include <string>

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

/// The verbose line of one iteration on std::cerr ("Iter    n, Eval    m: Best F = f"), out of
/// line so that the header reaches no <iostream> (a firmware that never prints links none).
void vnl_nonlinear_minimizer_print_iteration(int iterations, int evaluations, double best_f);

template <class T>
class vnl_nonlinear_minimizer_of {
 public:
  /// MINPACK's info codes and the line-search one, as upstream names them.
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
    FAILED_USER_REQUEST = 9,
    ABNORMAL_TERMINATION_IN_LNSRCH = 10
  };

  vnl_nonlinear_minimizer_of()
      : xtol(at_least_epsilon(kDefaultXtol)),
        ftol(at_least_epsilon(kDefaultFtol)),
        gtol(at_least_epsilon(kDefaultGtol)),
        epsfcn(at_least_epsilon(kDefaultEpsfcn)) {}
  virtual ~vnl_nonlinear_minimizer_of() = default;

  /// Stop when the relative reduction of the sum of squares is below v.
  void set_f_tolerance(T v) { ftol = v; }
  T get_f_tolerance() const { return ftol; }
  /// Stop when the relative change of x (scaled) is below v; as upstream, the forward-difference
  /// step becomes xtol / 1000.
  void set_x_tolerance(T v) {
    xtol = v;
    epsfcn = at_least_epsilon(xtol * kEpsfcnPerXtol);
  }
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
  /// With n > 0, the next n analytic Jacobians are compared with forward differences (LM).
  void set_check_derivatives(int n) { check_derivatives_ = n; }
  int get_check_derivatives() const { return check_derivatives_; }

  /// The error at the start and at the end (the best reached) of the last minimisation: RMS of
  /// the residuals for LM, the cost for the vnl_cost_function minimisers.
  T get_start_error() const { return start_error_; }
  T get_end_error() const { return end_error_; }
  /// Residual evaluations and (for lmder: the same count; for lmdif: progress calls) iterations.
  int get_num_evaluations() const { return num_evaluations_; }
  int get_num_iterations() const { return num_iterations_; }
  ReturnCodes get_failure_code() const { return failure_code_; }
  /// True when the last minimisation ran and lowered the error.
  bool obj_value_reduced() const {
    return failure_code_ != ERROR_FAILURE && failure_code_ != ERROR_DODGY_INPUT && end_error_ < start_error_;
  }
  /// The covariance of the estimate; empty unless a minimiser computes it.
  virtual const vnl_matrix<T>& get_covariance() { return covariance_; }
  virtual std::string is_a() const { return "vnl_nonlinear_minimizer"; }
  virtual bool is_class(const std::string& s) const { return s == "vnl_nonlinear_minimizer"; }

 protected:
  // Upstream's defaults, converted at compile time (no double arithmetic at run time).
  static constexpr T kDefaultXtol = T(1e-8);
  static constexpr T kDefaultFtol = T(1e-10);
  static constexpr T kDefaultGtol = T(1e-5);
  static constexpr T kDefaultEpsfcn = T(1e-11);
  static constexpr T kEpsfcnPerXtol = T(1e-3);

  static T at_least_epsilon(T v) {
    const T eps = std::numeric_limits<T>::epsilon();
    return v < eps ? eps : v;
  }

  /// Zeroes the counters and errors before a minimisation.
  void reset() {
    num_iterations_ = 0;
    num_evaluations_ = 0;
    start_error_ = T(0);
    end_error_ = T(0);
  }
  /// Records one evaluation of value v: the first is the start error, the lowest the end error.
  void report_eval(T v) {
    if (num_evaluations_ == 0) {
      start_error_ = v;
      end_error_ = v;
    }
    if (v < end_error_) end_error_ = v;
    ++num_evaluations_;
  }
  /// Records one iteration; returns true to ask the minimiser to stop (never, by default).
  virtual bool report_iter() {
    ++num_iterations_;
    if (verbose_)
      vnl_nonlinear_minimizer_print_iteration(num_iterations_, num_evaluations_, static_cast<double>(end_error_));
    return false;
  }

  T xtol;
  T ftol;
  T gtol;
  T epsfcn;
  int maxfev = 2000;
  bool trace = false;
  bool verbose_ = false;
  int check_derivatives_ = 0;
  T start_error_ = T(0);
  T end_error_ = T(0);
  int num_evaluations_ = 0;
  int num_iterations_ = 0;
  ReturnCodes failure_code_ = ERROR_FAILURE;
  vnl_matrix<T> covariance_;
};

/// Upstream's vnl_nonlinear_minimizer: on double, whatever `real` is.
using vnl_nonlinear_minimizer = vnl_nonlinear_minimizer_of<double>;

}  // inline namespace edgetrack_ports
