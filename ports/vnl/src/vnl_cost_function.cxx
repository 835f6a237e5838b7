// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_cost_function.h"

#include <cmath>

#include "vcl/vcl_compiler.h"

inline namespace edgetrack_ports {

void vnl_cost_function::compute(const vnl_vector<double>& x, double* val, vnl_vector<double>* g) {
  if (val) *val = this->f(x);
  if (g) this->gradf(x, *g);
}

double vnl_cost_function::f(const vnl_vector<double>& x) {
  if (in_default_) vcl_abort("vnl_cost_function: a subclass must override f, gradf or compute");
  double val = NAN;
  in_default_ = true;
  this->compute(x, &val, nullptr);
  in_default_ = false;
  return val;
}

void vnl_cost_function::gradf(const vnl_vector<double>& x, vnl_vector<double>& g) {
  if (in_default_) vcl_abort("vnl_cost_function: a subclass must override f, gradf or compute");
  in_default_ = true;
  this->compute(x, nullptr, &g);
  in_default_ = false;
}

void vnl_cost_function::fdgradf(const vnl_vector<double>& x, vnl_vector<double>& gradient, double stepsize) {
  vnl_vector<double> tx = x;
  for (int i = 0; i < dim; ++i) {
    const double plus = x[i] + stepsize, minus = x[i] - stepsize;
    tx[i] = plus;
    const double f_plus = this->f(tx);
    tx[i] = minus;
    const double f_minus = this->f(tx);
    gradient[i] = (f_plus - f_minus) / (plus - minus);
    tx[i] = x[i];
  }
}

vnl_vector<double> vnl_cost_function::gradf(const vnl_vector<double>& x) {
  vnl_vector<double> g(dim);
  this->gradf(x, g);
  return g;
}

vnl_vector<double> vnl_cost_function::fdgradf(const vnl_vector<double>& x) {
  vnl_vector<double> g(dim);
  this->fdgradf(x, g);
  return g;
}

}  // inline namespace edgetrack_ports
