// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_linear_system.h: an abstract linear system A x = b given by the
/// products A x and A^T y (for iterative solvers), with its residual measures.
#pragma once

#ifdef vnl_linear_system_h_
#error "edgetrack's drop-in vnl/vnl_linear_system.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_linear_system {
 public:
  vnl_linear_system(unsigned int number_of_unknowns, unsigned int number_of_residuals)
      : p_(number_of_unknowns), n_(number_of_residuals) {}
  virtual ~vnl_linear_system() = default;

  /// y = A x.
  virtual void multiply(const vnl_vector<double>& x, vnl_vector<double>& y) const = 0;
  /// x = A^T y.
  virtual void transpose_multiply(const vnl_vector<double>& y, vnl_vector<double>& x) const = 0;
  virtual void get_rhs(vnl_vector<double>& b) const = 0;
  /// px = P x for a preconditioner P; the identity unless overridden.
  virtual void apply_preconditioner(const vnl_vector<double>& x, vnl_vector<double>& px) const { px = x; }
  unsigned int get_number_of_unknowns() const { return p_; }
  unsigned int get_number_of_residuals() const { return n_; }
  /// rms(A x - b), and that over rms(b).
  double get_rms_error(const vnl_vector<double>& x) const;
  double get_relative_residual(const vnl_vector<double>& x) const;

 protected:
  unsigned int p_;
  unsigned int n_;
};

inline double vnl_linear_system::get_rms_error(const vnl_vector<double>& x) const {
  vnl_vector<double> residual(n_), b(n_);
  multiply(x, residual);
  get_rhs(b);
  return (residual - b).rms();
}

inline double vnl_linear_system::get_relative_residual(const vnl_vector<double>& x) const {
  vnl_vector<double> b(n_);
  get_rhs(b);
  return get_rms_error(x) / b.rms();
}

}  // inline namespace edgetrack_ports
