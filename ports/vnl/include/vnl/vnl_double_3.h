// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_3.h: vnl_double_3, a fixed vector of 3 doubles.
#pragma once

#ifdef vnl_double_3_h_
#error "edgetrack's drop-in vnl/vnl_double_3.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

using vnl_double_3 = vnl_vector_fixed<double, 3>;

}  // inline namespace edgetrack_ports
