// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_1x3.h: vnl_float_1x3, a fixed 1 x 3 matrix of floats.
#pragma once

#ifdef vnl_float_1x3_h_
#error "edgetrack's drop-in vnl/vnl_float_1x3.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

using vnl_float_1x3 = vnl_matrix_fixed<float, 1, 3>;

}  // inline namespace edgetrack_ports
