// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_least_squares_function_of for the configured `real` when it is not double
/// (the double file has that one).
#include "real/real.h"
#include "vnl/vnl_least_squares_function.hxx"

#if !defined(EDGETRACK_REAL_DOUBLE)
inline namespace edgetrack_ports {

VNL_LEAST_SQUARES_FUNCTION_INSTANTIATE(real);
}  // inline namespace edgetrack_ports
#endif
