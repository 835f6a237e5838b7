// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_cost_function.h: a scalar function of a vector of unknowns, with
/// its gradient, for the minimisers. Override f and gradf, or compute (which gives both);
/// each default calls the other, so override at least one.
#pragma once

#ifdef vnl_cost_function_h_
#error "edgetrack's drop-in vnl/vnl_cost_function.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_unary_function.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_cost_function : public vnl_unary_function<double, vnl_vector<double>> {
 public:
  vnl_cost_function() = default;
  explicit vnl_cost_function(int number_of_unknowns) : dim(number_of_unknowns) {}
  ~vnl_cost_function() override = default;

  double f(const vnl_vector<double>& x) override;
  virtual void gradf(const vnl_vector<double>& x, vnl_vector<double>& gradient);
  /// Fills *f and/or *g (either may be null).
  virtual void compute(const vnl_vector<double>& x, double* f, vnl_vector<double>* g);
  int get_number_of_unknowns() const { return dim; }
  /// The gradient by central differences with step `stepsize`.
  void fdgradf(const vnl_vector<double>& x, vnl_vector<double>& gradient, double stepsize = 1e-5);
  /// The error a minimiser reports for value f (f itself unless overridden).
  virtual double reported_error(double f_value) { return f_value; }
  vnl_vector<double> gradf(const vnl_vector<double>& x);
  vnl_vector<double> fdgradf(const vnl_vector<double>& x);

 protected:
  void set_number_of_unknowns(int number_of_unknowns) { dim = number_of_unknowns; }

 public:
  int dim = 0;

 private:
  bool in_default_ = false;  // catches a subclass that overrides neither f, gradf nor compute
};

}  // inline namespace edgetrack_ports
