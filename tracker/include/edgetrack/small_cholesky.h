// SPDX-License-Identifier: BSD-3-Clause
/// The Cholesky factorisation of a small symmetric matrix on the stack (the pose's 6 x 6 normal
/// equations and information matrix): vnl_cholesky's vnl_matrix would allocate per frame.
#pragma once

#include <cmath>

#include "real/real.h"

namespace edgetrack {

/// Factors the lower triangle of the leading n x n block of `a` in place as L L^T; false, with
/// `a` partly overwritten, when a pivot is not above `least_pivot` (a direction the matrix does
/// not see, or one lost to rounding). One reciprocal per column, not a division per entry: an
/// ARMv5TE has no divider.
template <int N>
bool cholesky_in_place(real (&a)[N][N], int n, const real& least_pivot) {
  using std::sqrt;
  for (int k = 0; k < n; ++k) {
    real pivot = a[k][k];
    for (int j = 0; j < k; ++j) pivot -= a[k][j] * a[k][j];
    if (!(pivot > least_pivot)) return false;
    a[k][k] = sqrt(pivot);
    const real inv = real(1) / a[k][k];
    for (int i = k + 1; i < n; ++i) {
      real s = a[i][k];
      for (int j = 0; j < k; ++j) s -= a[i][j] * a[k][j];
      a[i][k] = s * inv;
    }
  }
  return true;
}

}  // namespace edgetrack
