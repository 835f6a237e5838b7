// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_3x3.h: vnl_double_3x3, a fixed 3 x 3 matrix of doubles.
#pragma once

#ifdef vnl_double_3x3_h_
#error "edgetrack's drop-in vnl/vnl_double_3x3.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

using vnl_double_3x3 = vnl_matrix_fixed<double, 3, 3>;

}  // inline namespace edgetrack_ports
