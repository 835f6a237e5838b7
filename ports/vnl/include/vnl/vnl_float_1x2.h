// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_1x2.h: vnl_float_1x2, a fixed 1 x 2 matrix of floats.
#pragma once

#ifdef vnl_float_1x2_h_
#error "edgetrack's drop-in vnl/vnl_float_1x2.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

using vnl_float_1x2 = vnl_matrix_fixed<float, 1, 2>;

}  // inline namespace edgetrack_ports
