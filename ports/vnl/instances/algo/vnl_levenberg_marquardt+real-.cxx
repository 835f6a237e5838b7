// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_levenberg_marquardt_of for the configured `real` when it is not double (the
/// double file has that one).
#include "real/real.h"
#include "vnl/algo/vnl_levenberg_marquardt.hxx"

#if !defined(EDGETRACK_REAL_DOUBLE)
inline namespace edgetrack_ports {

VNL_LEVENBERG_MARQUARDT_INSTANTIATE(real);
}  // inline namespace edgetrack_ports
#endif
