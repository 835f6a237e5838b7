// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_identity_3x3.h: the 3x3 identity as a vnl_double_3x3.
#pragma once

#ifdef vnl_identity_3x3_h_
#error "edgetrack's drop-in vnl/vnl_identity_3x3.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_double_3x3.h"

inline namespace edgetrack_ports {

struct vnl_identity_3x3 : public vnl_double_3x3 {
  vnl_identity_3x3() { set_identity(); }
};

}  // inline namespace edgetrack_ports
