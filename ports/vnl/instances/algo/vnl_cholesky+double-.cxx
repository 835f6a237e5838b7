// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_cholesky for double (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_cholesky.hxx"

inline namespace edgetrack_ports {

VNL_CHOLESKY_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
