// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_2x1.h: vnl_double_2x1, a fixed 2 x 1 matrix of doubles.
#pragma once

#ifdef vnl_double_2x1_h_
#error "edgetrack's drop-in vnl/vnl_double_2x1.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

using vnl_double_2x1 = vnl_matrix_fixed<double, 2, 1>;

}  // inline namespace edgetrack_ports
