// SPDX-License-Identifier: BSD-3-Clause
/// The pose step's optional solver (PoseParams::solver): Levenberg-Marquardt on the n x n normal
/// equations J^T J x = -J^T f instead of MINPACK's QR of the m x n Jacobian. Forming J^T J
/// costs n(n+1)/2 dot products over the m residuals and the 6 x 6 Cholesky factorisation is
/// tiny, where lmder's Householder QR with pivoting and its trust-region steps touch the whole
/// Jacobian several times. The price is the squared condition number of J^T J, which for six
/// pose parameters and tens of spread control points stays small once the columns are scaled
/// to unit norm (as lmder's diag scales them).
#pragma once

#include "netlib/minpack.h"
#include "real/real.h"

namespace edgetrack {

/// The largest n normal_equations_lm solves (the pose's six parameters).
constexpr int kMaxNormalUnknowns = 6;

/// Minimises the sum of squares of the m residuals of `fcn` (lmder's callback and conventions:
/// iflag 1 fills fvec, 2 fills the column-major fjac at the last evaluated x) over x (n <= 6,
/// starting at the given x), with the same stopping rules and return codes as lmder: 1 when an
/// accepted step reduced the sum of squares by at most ftol relatively, 2 when it was at most
/// xtol relative to |D x| (D the column norms), 4 when the largest cosine between f and a column
/// of J is at most gtol, 5 after maxfev evaluations, 0 for bad input, or the callback's negative
/// value. Each iteration tries the Gauss-Newton step first and raises the damping (times the
/// scaled diagonal) tenfold after each step that does not reduce the sum of squares.
/// nfev and njev count residual and Jacobian evaluations.
int normal_equations_lm(netlib::minpack_funcder_mn<real> fcn, void* p, int m, int n, real* x, real* fvec, real* fjac,
                        int ldfjac, real ftol, real xtol, real gtol, int maxfev, real* trial_fvec, int* nfev, int* njev);

}  // namespace edgetrack
