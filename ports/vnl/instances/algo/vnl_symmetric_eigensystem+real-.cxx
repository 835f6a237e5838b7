// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_symmetric_eigensystem for the configured `real` when it is fixed point (a double or float
/// `real` is already instantiated by the double and float files; upstream: core/vnl/algo/Templates/).
#include "real/real.h"
#include "vnl/algo/vnl_symmetric_eigensystem.hxx"

#if !defined(EDGETRACK_REAL_DOUBLE) && !defined(EDGETRACK_REAL_FLOAT)
inline namespace edgetrack_ports {

VNL_SYMMETRIC_EIGENSYSTEM_INSTANTIATE(real);
}  // inline namespace edgetrack_ports
#endif
