// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_bracket_minimum.h: from a starting pair a, b, walks downhill
/// (golden-ratio steps, with parabolic jumps where the fit allows) until a < b < c (or a > b >
/// c) with f(b) below f(a) and f(c), so [a, c] brackets a minimum of the one-variable f.
#pragma once

#ifdef vnl_bracket_minimum_h_
#error "edgetrack's drop-in vnl/algo/vnl_bracket_minimum.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_cost_function.h"

inline namespace edgetrack_ports {

void vnl_bracket_minimum(vnl_cost_function& f, double& a, double& b, double& c, double& fa, double& fb,
                         double& fc);

}  // inline namespace edgetrack_ports
