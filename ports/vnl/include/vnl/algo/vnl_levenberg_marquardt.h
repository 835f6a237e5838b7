// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_levenberg_marquardt.h: Levenberg-Marquardt minimisation of a
/// vnl_least_squares_function over our MINPACK (netlib/minpack.h): lmder when the function
/// has a Jacobian, lmdif (forward differences) otherwise. Templated on the scalar as
/// vnl_levenberg_marquardt_of<T> (the tracker uses it on `real`); `vnl_levenberg_marquardt` is
/// upstream's class, on double in every build (soft-float on the ARM target, the user's choice).
///
/// Counters follow upstream: with lmder, get_num_iterations() and get_num_evaluations() both
/// count residual evaluations; get_num_jacobian_evaluations() gives MINPACK's iterations.
#pragma once

#ifdef vnl_levenberg_marquardt_h_
#error "edgetrack's drop-in vnl/algo/vnl_levenberg_marquardt.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

#include "vnl/vnl_least_squares_function.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_nonlinear_minimizer.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_levenberg_marquardt_of : public vnl_nonlinear_minimizer_of<T> {
 public:
  using ReturnCodes = typename vnl_nonlinear_minimizer_of<T>::ReturnCodes;

  /// Keeps a reference to f, which must outlive the minimiser. Default maxfev: 400 * unknowns.
  explicit vnl_levenberg_marquardt_of(vnl_least_squares_function_of<T>& f);

  /// Minimises from x, leaving the estimate in x; true when a tolerance was met (codes 1-4).
  bool minimize(vnl_vector<T>& x);
  bool minimize_using_gradient(vnl_vector<T>& x);
  bool minimize_without_gradient(vnl_vector<T>& x);
  /// The same on a fixed-size estimate (upstream has N = 1 to 4).
  template <unsigned int N>
  bool minimize(vnl_vector_fixed<T, N>& x) {
    vnl_vector<T> y = x.as_vector();
    const bool converged = minimize(y);
    x.copy_in(y.data_block());
    return converged;
  }

  /// Writes what ended the last minimisation, the counts and the start/end RMS errors.
  void diagnose_outcome(std::ostream& s) const;
  void diagnose_outcome() const;

  /// Jacobian evaluations of the last lmder run (MINPACK's iteration count); 0 after lmdif.
  int get_num_jacobian_evaluations() const { return num_jacobian_evaluations_; }
  /// J^T J at the solution, from MINPACK's final R and permutation: P R^T R P^T.
  const vnl_matrix<T>& get_JtJ();

 private:
  static int lmder_callback(void* self, int m, int n, const T* x, T* fx, T* fjac, int ldfjac, int iflag);
  static int lmdif_callback(void* self, int m, int n, const T* x, T* fx, int iflag);
  bool input_is_valid(const vnl_vector<T>& x);
  /// With check_derivatives set, prints the Jacobian entries that differ from forward differences.
  void check_jacobian(const vnl_vector<T>& x, const vnl_matrix<T>& jacobian);
  bool outcome_is_success() const;
  /// Sizes the buffers the callbacks hand to f and gradf (no allocation per evaluation).
  void prepare_buffers(int m, int n);

  vnl_least_squares_function_of<T>* f_;
  vnl_matrix<T> fdjac_;  ///< MINPACK's column-major m x n work matrix, stored as n x m
  vnl_vector<int> ipvt_;
  vnl_vector<T> x_buffer_;
  vnl_vector<T> fx_buffer_;
  vnl_matrix<T> jacobian_buffer_;
  vnl_matrix<T> jtj_;
  int num_jacobian_evaluations_ = 0;
  bool start_error_set_ = false;
};

/// Upstream's vnl_levenberg_marquardt, on double whatever `real` is.
class vnl_levenberg_marquardt : public vnl_levenberg_marquardt_of<double> {
 public:
  vnl_levenberg_marquardt(vnl_least_squares_function& f) : vnl_levenberg_marquardt_of<double>(f) {}  // NOLINT: implicit as upstream
};

/// Upstream's one-call form: minimises f from initial_estimate and returns the estimate.
vnl_vector<double> vnl_levenberg_marquardt_minimize(vnl_least_squares_function& f,
                                                    const vnl_vector<double>& initial_estimate);

}  // inline namespace edgetrack_ports
