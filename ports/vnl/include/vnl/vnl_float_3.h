// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_3.h: vnl_float_3, a fixed vector of 3 floats.
#pragma once

#ifdef vnl_float_3_h_
#error "edgetrack's drop-in vnl/vnl_float_3.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

using vnl_float_3 = vnl_vector_fixed<float, 3>;

}  // inline namespace edgetrack_ports
