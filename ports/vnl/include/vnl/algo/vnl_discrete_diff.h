// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_discrete_diff.h: the Jacobian of a
/// vnl_least_squares_function by forward differences (f(x + h_j e_j) - f(x)) / h_j or symmetric
/// ones (f(x + h_j e_j) - f(x - h_j e_j)) / 2 h_j, with one step for all unknowns or one each.
/// Each returns false as soon as the function reports a failure.
#pragma once

#ifdef vnl_discrete_diff_h_
#error "edgetrack's drop-in vnl/algo/vnl_discrete_diff.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_least_squares_function;

bool vnl_discrete_diff_fwd(vnl_least_squares_function* lsf, double h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J);
bool vnl_discrete_diff_fwd(vnl_least_squares_function* lsf, const vnl_vector<double>& h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J);
/// The same with y = f(x) already computed.
bool vnl_discrete_diff_fwd(vnl_least_squares_function* lsf, const vnl_vector<double>& h, const vnl_vector<double>& x,
                           const vnl_vector<double>& y, vnl_matrix<double>& J);
bool vnl_discrete_diff_sym(vnl_least_squares_function* lsf, double h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J);
bool vnl_discrete_diff_sym(vnl_least_squares_function* lsf, const vnl_vector<double>& h, const vnl_vector<double>& x,
                           vnl_matrix<double>& J);
/// Prints to stderr how far lsf's gradf is from symmetric differences with step 1e-4: the
/// Frobenius norm of the difference and the cosine between the two Jacobians.
void vnl_discrete_diff_test_lsf(vnl_least_squares_function* lsf, const vnl_vector<double>& x);

}  // inline namespace edgetrack_ports
