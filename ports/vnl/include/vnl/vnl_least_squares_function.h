// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_least_squares_function.h: the abstract residual function that
/// vnl_levenberg_marquardt minimises, built from the number of unknowns, the number of
/// residuals and whether it provides a Jacobian. Templated on the scalar as
/// vnl_least_squares_function_of<T> (the tracker uses it on `real`); `vnl_least_squares_function`
/// is upstream's class, on double in every build.
#pragma once

#ifdef vnl_least_squares_function_h_
#error "edgetrack's drop-in vnl/vnl_least_squares_function.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_least_squares_function_of {
 public:
  enum UseGradient { no_gradient, use_gradient };

  /// Set by f or gradf to make the minimiser stop with ERROR_FAILURE.
  bool failure = false;

  vnl_least_squares_function_of(unsigned int number_of_unknowns, unsigned int number_of_residuals,
                                UseGradient g = use_gradient)
      : p_(number_of_unknowns), n_(number_of_residuals), use_gradient_(g == use_gradient) {}
  virtual ~vnl_least_squares_function_of() = default;

  void throw_failure() { failure = true; }
  void clear_failure() { failure = false; }

  /// The residuals fx (size get_number_of_residuals()) at x (size get_number_of_unknowns()).
  virtual void f(const vnl_vector<T>& x, vnl_vector<T>& fx) = 0;
  /// The Jacobian d fx / d x, residuals by unknowns. The default uses forward differences
  /// (upstream's only warns), with step sqrt(epsilon).
  virtual void gradf(const vnl_vector<T>& x, vnl_matrix<T>& jacobian);
  /// Central-difference Jacobian with absolute step `stepsize`, as upstream.
  void fdgradf(const vnl_vector<T>& x, vnl_matrix<T>& jacobian, T stepsize);
  /// Forward-difference Jacobian with absolute step `stepsize`, as upstream.
  void ffdgradf(const vnl_vector<T>& x, vnl_matrix<T>& jacobian, T stepsize);
  /// Called once per iteration with the current estimate; does nothing by default.
  virtual void trace(int iteration, const vnl_vector<T>& x, const vnl_vector<T>& fx);
  /// RMS of the residuals at x.
  T rms(const vnl_vector<T>& x);

  unsigned int get_number_of_unknowns() const { return p_; }
  unsigned int get_number_of_residuals() const { return n_; }
  bool has_gradient() const { return use_gradient_; }

 protected:
  /// Resizes the problem (upstream's protected init).
  void init(unsigned int number_of_unknowns, unsigned int number_of_residuals) {
    p_ = number_of_unknowns;
    n_ = number_of_residuals;
  }

  unsigned int p_;
  unsigned int n_;
  bool use_gradient_;
};

/// Upstream's vnl_least_squares_function, on double whatever `real` is; as upstream, it warns
/// on stderr when built with more unknowns than residuals.
class vnl_least_squares_function : public vnl_least_squares_function_of<double> {
 public:
  vnl_least_squares_function(unsigned int number_of_unknowns, unsigned int number_of_residuals,
                             UseGradient g = use_gradient);
};

}  // inline namespace edgetrack_ports
