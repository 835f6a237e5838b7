// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates our MINPACK routines for double, for upstream's vnl_levenberg_marquardt.
#include "netlib/minpack.hxx"

inline namespace edgetrack_ports {

NETLIB_MINPACK_INSTANTIATE(double)

}  // inline namespace edgetrack_ports
