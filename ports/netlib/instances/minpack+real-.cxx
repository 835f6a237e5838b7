// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates our MINPACK routines for the configured `real` when it is not double (the double
/// file has that one).
#include "netlib/minpack.hxx"
#include "real/real.h"

#if !defined(EDGETRACK_REAL_DOUBLE)
inline namespace edgetrack_ports {

NETLIB_MINPACK_INSTANTIATE(real)
}  // inline namespace edgetrack_ports
#endif
