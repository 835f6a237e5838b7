// SPDX-License-Identifier: BSD-3-Clause
/// Levenberg-Marquardt on the scaled 6 x 6 normal equations, with a Cholesky factorisation.
#include "edgetrack/normal_equations_lm.h"

#include <cmath>

#include "edgetrack/small_cholesky.h"
#include "real/sum_of_products.h"

namespace edgetrack {
namespace {

/// A damped system whose smallest Cholesky pivot falls below this (the scaled matrix has a unit
/// diagonal) is treated as singular: the damping grows instead. A condition number of 10^5 is
/// also about where S40.23's 23 fraction bits stop resolving the step.
const real kSmallestPivot = real(1e-5);
/// The damping the first rejected Gauss-Newton step (or a singular system) starts from, relative
/// to the unit diagonal; each further rejection multiplies it by ten, up to kLargestDamping.
const real kFirstDamping = real(1e-3);
const real kLargestDamping = real(1e6);

real dot(int m, const real* a, const real* b) { return sum_of_products(m, a, b); }

/// The scaled normal equations at one x: s = D^-1 J^T J D^-1 (lower triangle, unit diagonal
/// where a column is not zero), g = D^-1 J^T f and d = D's diagonal, the column norms of J.
struct ScaledSystem {
  real s[kMaxNormalUnknowns][kMaxNormalUnknowns] = {};
  real g[kMaxNormalUnknowns] = {};
  real d[kMaxNormalUnknowns] = {};
};

ScaledSystem scaled_system(int m, int n, const real* fjac, int ldfjac, const real* fvec) {
  using std::sqrt;
  ScaledSystem sys;
  real a[kMaxNormalUnknowns][kMaxNormalUnknowns];
  for (int j = 0; j < n; ++j) {
    const real* column = fjac + j * ldfjac;
    for (int k = 0; k <= j; ++k) a[j][k] = dot(m, column, fjac + k * ldfjac);
    sys.d[j] = a[j][j] > real(0) ? sqrt(a[j][j]) : real(1);
    sys.g[j] = dot(m, column, fvec) / sys.d[j];
  }
  // Divided twice, not by d_j d_k: in fixed point the product would lose the small entries.
  for (int j = 0; j < n; ++j)
    for (int k = 0; k <= j; ++k) sys.s[j][k] = a[j][k] / sys.d[j] / sys.d[k];
  return sys;
}

/// Solves (s + damping I) y = -g by Cholesky; false when a pivot is not above kSmallestPivot.
bool damped_step(const ScaledSystem& sys, int n, const real& damping, real* y) {
  real l[kMaxNormalUnknowns][kMaxNormalUnknowns];
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k <= j; ++k) l[j][k] = sys.s[j][k];
    l[j][j] += damping;
  }
  if (!cholesky_in_place(l, n, kSmallestPivot)) return false;
  for (int i = 0; i < n; ++i) {  // L z = -g
    real sum = -sys.g[i];
    for (int k = 0; k < i; ++k) sum -= l[i][k] * y[k];
    y[i] = sum / l[i][i];
  }
  for (int i = n - 1; i >= 0; --i) {  // L^T y = z
    real sum = y[i];
    for (int k = i + 1; k < n; ++k) sum -= l[k][i] * y[k];
    y[i] = sum / l[i][i];
  }
  return true;
}

real norm(int n, const real* v) {
  using std::sqrt;
  return sqrt(dot(n, v, v));
}

}  // namespace

int normal_equations_lm(netlib::minpack_funcder_mn<real> fcn, void* p, int m, int n, real* x, real* fvec, real* fjac,
                        int ldfjac, real ftol, real xtol, real gtol, int maxfev, real* trial_fvec, int* nfev,
                        int* njev) {
  using std::fabs;
  *nfev = 0;
  *njev = 0;
  if (n < 1 || n > kMaxNormalUnknowns || m < n || ldfjac < m || maxfev < 1) return 0;
  int iflag = fcn(p, m, n, x, fvec, fjac, ldfjac, 1);
  *nfev = 1;
  if (iflag < 0) return iflag;
  real cost = dot(m, fvec, fvec);
  real damping(0);
  for (;;) {  // one Jacobian per iteration
    iflag = fcn(p, m, n, x, fvec, fjac, ldfjac, 2);
    ++*njev;
    if (iflag < 0) return iflag;
    const ScaledSystem sys = scaled_system(m, n, fjac, ldfjac, fvec);
    // lmder's gradient test: the largest cosine between f and a column of J.
    const real fnorm = norm(m, fvec);
    real gnorm(0);
    for (int j = 0; j < n && fnorm > real(0); ++j) {
      const real cosine = fabs(sys.g[j]) / fnorm;
      if (cosine > gnorm) gnorm = cosine;
    }
    if (gnorm <= gtol) return 4;
    for (;;) {  // damp until a step reduces the sum of squares
      real y[kMaxNormalUnknowns] = {}, trial[kMaxNormalUnknowns] = {}, scaled_x[kMaxNormalUnknowns] = {};
      if (!damped_step(sys, n, damping, y)) {
        if (damping >= kLargestDamping) return 5;  // no usable step: x stays LM's best estimate
        damping = damping == real(0) ? kFirstDamping : real(10) * damping;
        continue;
      }
      for (int j = 0; j < n; ++j) trial[j] = x[j] + y[j] / sys.d[j];
      iflag = fcn(p, m, n, trial, trial_fvec, fjac, ldfjac, 1);
      ++*nfev;
      if (iflag < 0) return iflag;
      const real trial_cost = dot(m, trial_fvec, trial_fvec);
      if (trial_cost < cost) {
        const real reduction = (cost - trial_cost) / cost;
        for (int j = 0; j < n; ++j) {
          x[j] = trial[j];
          scaled_x[j] = sys.d[j] * x[j];
        }
        for (int i = 0; i < m; ++i) fvec[i] = trial_fvec[i];
        cost = trial_cost;
        damping = real(0.1) * damping < kFirstDamping ? real(0) : real(0.1) * damping;
        const bool f_converged = reduction <= ftol, x_converged = norm(n, y) <= xtol * norm(n, scaled_x);
        if (f_converged || x_converged) return f_converged ? (x_converged ? 3 : 1) : 2;
        if (*nfev >= maxfev) return 5;
        break;
      }
      if (*nfev >= maxfev) return 5;
      if (damping >= kLargestDamping) return 5;
      damping = damping == real(0) ? kFirstDamping : real(10) * damping;
    }
  }
}

}  // namespace edgetrack
