// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_bessel.h: Bessel functions of the first kind J_n(x) in double
/// (the C++17 library's cyl_bessel_j; upstream uses Miller's downward recurrence). J_n(-x) =
/// (-1)^n J_n(x) extends them to negative x, as upstream's accept it.
#pragma once

#ifdef vnl_bessel_h_
#error "edgetrack's drop-in vnl/vnl_bessel.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

double vnl_bessel(unsigned n, double x);
double vnl_bessel0(double x);
/// J[i] = J_i(x) for i = 0..n_max (J is resized to n_max + 1).
void vnl_bessel(unsigned n_max, double x, vnl_vector<double>& J);

}  // inline namespace edgetrack_ports
