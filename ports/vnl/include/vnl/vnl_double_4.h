// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_4.h: vnl_double_4, a fixed vector of 4 doubles.
#pragma once

#ifdef vnl_double_4_h_
#error "edgetrack's drop-in vnl/vnl_double_4.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

using vnl_double_4 = vnl_vector_fixed<double, 4>;

}  // inline namespace edgetrack_ports
