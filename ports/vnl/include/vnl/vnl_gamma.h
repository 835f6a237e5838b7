// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_gamma.h: the gamma function and its relatives in double.
/// log gamma is the C library's lgamma (upstream: a 6-term Lanczos fit good to 3e-11); the
/// incomplete gamma ratios use the series for x < a + 1 and Lentz's continued fraction
/// otherwise, each to 1e-15 relative; digamma uses the recurrence up to 12 and the asymptotic
/// series there (error below 1e-14 for x > 0).
#pragma once

#ifdef vnl_gamma_h_
#error "edgetrack's drop-in vnl/vnl_gamma.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>

#include "vnl/vnl_math.h"

inline namespace edgetrack_ports {

double vnl_log_gamma(double x);
inline double vnl_gamma(double x) { return std::exp(vnl_log_gamma(x)); }
/// The normalised lower incomplete gamma function P(a, x), a > 0, x >= 0.
double vnl_gamma_p(double a, double x);
/// Q(a, x) = 1 - P(a, x).
double vnl_gamma_q(double a, double x);
/// P(chi^2 < chi2) for n_dof degrees of freedom.
inline double vnl_cum_prob_chi2(int n_dof, double chi2) { return vnl_gamma_p(n_dof * 0.5, chi2 * 0.5); }
/// d/dx log gamma(x).
double vnl_digamma(double x);

}  // inline namespace edgetrack_ports
