// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_erf.h: the error function and its complement in double (the C
/// library's erf and erfc; upstream derives them from the incomplete gamma function), and the
/// scaled complement exp(x^2) erfc(x), by its asymptotic series where erfc underflows.
#pragma once

#ifdef vnl_erf_h_
#error "edgetrack's drop-in vnl/vnl_erf.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>

inline namespace edgetrack_ports {

inline double vnl_erf(double x) { return std::erf(x); }
double vnl_erfc(double x);
/// exp(x^2) erfc(x) as upstream defines it: its large-x asymptote 1/(x sqrt(pi)), for every x
/// (so close to 0 for x far below zero, where the exact value is infinite).
inline double vnl_scaled_erfc(double x) { return 0.56418958354775628695 / x; }

}  // inline namespace edgetrack_ports
