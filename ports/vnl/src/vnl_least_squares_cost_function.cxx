// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_least_squares_cost_function.h"

vnl_least_squares_cost_function::vnl_least_squares_cost_function(vnl_least_squares_function* f)
    : vnl_cost_function(static_cast<int>(f->get_number_of_unknowns())),
      storage_(f->get_number_of_residuals()),
      jacobian_(f->get_number_of_residuals(), f->get_number_of_unknowns()),
      f_(f) {}

vnl_vector<real> vnl_least_squares_cost_function::residuals_at(const vnl_vector<double>& x) {
  vnl_vector<real> x_real(x.size());
  for (unsigned i = 0; i < x.size(); ++i) x_real[i] = real(x[i]);
  f_->f(x_real, storage_);
  return x_real;
}

double vnl_least_squares_cost_function::f(const vnl_vector<double>& x) {
  residuals_at(x);
  double sum = 0;
  for (unsigned r = 0; r < storage_.size(); ++r)
    sum += static_cast<double>(storage_[r]) * static_cast<double>(storage_[r]);
  return sum;
}

void vnl_least_squares_cost_function::gradf(const vnl_vector<double>& x, vnl_vector<double>& gradient) {
  if (!f_->has_gradient()) return;
  const vnl_vector<real> x_real = residuals_at(x);
  f_->gradf(x_real, jacobian_);
  for (unsigned c = 0; c < jacobian_.columns(); ++c) {
    double sum = 0;
    for (unsigned r = 0; r < jacobian_.rows(); ++r) {
      sum += static_cast<double>(storage_[r]) * static_cast<double>(jacobian_(r, c));
    }
    gradient[c] = 2 * sum;
  }
}
