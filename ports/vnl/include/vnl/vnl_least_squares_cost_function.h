// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_least_squares_cost_function.h: a vnl_least_squares_function seen
/// as a vnl_cost_function, f(x) = |fx|^2 with gradient 2 J^T fx (left untouched, as upstream,
/// when the least-squares function has no Jacobian). On double, as upstream.
#pragma once

#ifdef vnl_least_squares_cost_function_h_
#error "edgetrack's drop-in vnl/vnl_least_squares_cost_function.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_least_squares_function.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_least_squares_cost_function : public vnl_cost_function {
 public:
  explicit vnl_least_squares_cost_function(vnl_least_squares_function* f)
      : vnl_cost_function(static_cast<int>(f->get_number_of_unknowns())),
        storage_(f->get_number_of_residuals()),
        jacobian_(f->get_number_of_residuals(), f->get_number_of_unknowns()),
        f_(f) {}

  double f(const vnl_vector<double>& x) override {
    f_->f(x, storage_);
    return storage_.squared_magnitude();
  }
  void gradf(const vnl_vector<double>& x, vnl_vector<double>& gradient) override {
    if (!f_->has_gradient()) return;
    f_->f(x, storage_);
    f_->gradf(x, jacobian_);
    gradient = 2.0 * (storage_ * jacobian_);
  }

 protected:
  vnl_vector<double> storage_;
  vnl_matrix<double> jacobian_;
  vnl_least_squares_function* f_;
};

}  // inline namespace edgetrack_ports
