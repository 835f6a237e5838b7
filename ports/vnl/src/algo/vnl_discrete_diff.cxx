// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_discrete_diff.h"

#include <iostream>

#include "vnl/vnl_least_squares_function.h"

inline namespace edgetrack_ports {

bool vnl_discrete_diff_fwd(vnl_least_squares_function* lsf, double h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J) {
  return vnl_discrete_diff_fwd(lsf, vnl_vector<double>(x.size(), h), x, J);
}

bool vnl_discrete_diff_fwd(vnl_least_squares_function* lsf, const vnl_vector<double>& h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J) {
  vnl_vector<double> y(lsf->get_number_of_residuals());
  lsf->f(x, y);
  if (lsf->failure) return false;
  return vnl_discrete_diff_fwd(lsf, h, x, y, J);
}

bool vnl_discrete_diff_fwd(vnl_least_squares_function* lsf, const vnl_vector<double>& h, const vnl_vector<double>& x,
                           const vnl_vector<double>& y, vnl_matrix<double>& J) {
  const unsigned m = J.rows(), n = J.cols();
  vnl_vector<double> moved = x, y_moved(m);
  for (unsigned j = 0; j < n; ++j) {
    moved[j] = x[j] + h[j];
    lsf->f(moved, y_moved);
    if (lsf->failure) return false;
    moved[j] = x[j];
    for (unsigned i = 0; i < m; ++i) J(i, j) = (y_moved[i] - y[i]) / h[j];
  }
  return true;
}

bool vnl_discrete_diff_sym(vnl_least_squares_function* lsf, double h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J) {
  return vnl_discrete_diff_sym(lsf, vnl_vector<double>(x.size(), h), x, J);
}

bool vnl_discrete_diff_sym(vnl_least_squares_function* lsf, const vnl_vector<double>& h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J) {
  const unsigned m = J.rows(), n = J.cols();
  vnl_vector<double> moved = x, y_plus(m), y_minus(m);
  for (unsigned j = 0; j < n; ++j) {
    moved[j] = x[j] + h[j];
    lsf->f(moved, y_plus);
    if (lsf->failure) return false;
    moved[j] = x[j] - h[j];
    lsf->f(moved, y_minus);
    if (lsf->failure) return false;
    moved[j] = x[j];
    for (unsigned i = 0; i < m; ++i) J(i, j) = (y_plus[i] - y_minus[i]) / (2 * h[j]);
  }
  return true;
}

void vnl_discrete_diff_test_lsf(vnl_least_squares_function* lsf, const vnl_vector<double>& x) {
  const unsigned m = lsf->get_number_of_residuals(), n = lsf->get_number_of_unknowns();
  vnl_matrix<double> analytic(m, n), differences(m, n);
  lsf->gradf(x, analytic);
  vnl_discrete_diff_sym(lsf, 0.0001, x, differences);
  double dot = 0;
  for (unsigned i = 0; i < m; ++i)
    for (unsigned j = 0; j < n; ++j) dot += analytic(i, j) * differences(i, j);
  const double cosine = dot / (analytic.fro_norm() * differences.fro_norm());
  std::cerr << "vnl_discrete_diff_test_lsf: e = " << (analytic - differences).fro_norm() << "\nvnl_discrete_diff_test_lsf: t = "
            << cosine << '\n';
}

}  // inline namespace edgetrack_ports
