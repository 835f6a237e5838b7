// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_cross.h: the 2-D cross product (a scalar) and the 3-D one, for
/// vnl_vector (declared in vnl_vector.h) and vnl_vector_fixed.
#pragma once

#ifdef vnl_cross_h_
#error "edgetrack's drop-in vnl/vnl_cross.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T>
T vnl_cross_2d(const vnl_vector_fixed<T, 2>& a, const vnl_vector_fixed<T, 2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

}  // inline namespace edgetrack_ports
