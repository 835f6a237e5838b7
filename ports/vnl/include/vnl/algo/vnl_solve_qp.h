// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_solve_qp.h: minimise F(x) = x^T H x / 2 + g^T x (H symmetric)
/// subject to A x = b, to sum(x) = 0, or, with x >= 0 as well, to A x = b or sum(x) = 1. The
/// equality forms solve the KKT system [H A^T; A 0] [x; lambda] = [-g; b] (false when it is
/// singular). The non-negative forms take a feasible x and, as upstream's variant of the active
/// set strategy, repeatedly solve the equality problem on the free variables, step from x
/// towards that solution as far as every variable stays >= 0, and fix at zero the one that
/// stops the step, until the solution is feasible (false, with a message when verbose, for an
/// infeasible start or a singular system).
#pragma once

#ifdef vnl_solve_qp_h_
#error "edgetrack's drop-in vnl/algo/vnl_solve_qp.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

bool vnl_solve_qp_with_equality_constraints(const vnl_matrix<double>& H, const vnl_vector<double>& g,
                                            const vnl_matrix<double>& A, const vnl_vector<double>& b,
                                            vnl_vector<double>& x);
bool vnl_solve_qp_zero_sum(const vnl_matrix<double>& H, const vnl_vector<double>& g, vnl_vector<double>& x);
/// x must satisfy the constraints on entry: |A x - b|^2 < con_tol and x(i) >= 0.
bool vnl_solve_qp_with_non_neg_constraints(const vnl_matrix<double>& H, const vnl_vector<double>& g,
                                           const vnl_matrix<double>& A, const vnl_vector<double>& b,
                                           vnl_vector<double>& x, double con_tol = 1e-8, bool verbose = true);
/// x must satisfy sum(x) = 1 and x(i) >= 0 on entry.
bool vnl_solve_qp_non_neg_sum_one(const vnl_matrix<double>& H, const vnl_vector<double>& g, vnl_vector<double>& x,
                                  bool verbose = true);

}  // inline namespace edgetrack_ports
