// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_4x4.h: vnl_double_4x4, a fixed 4 x 4 matrix of doubles.
#pragma once

#ifdef vnl_double_4x4_h_
#error "edgetrack's drop-in vnl/vnl_double_4x4.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

using vnl_double_4x4 = vnl_matrix_fixed<double, 4, 4>;

}  // inline namespace edgetrack_ports
