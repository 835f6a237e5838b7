// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_cholesky for float (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_cholesky.hxx"

inline namespace edgetrack_ports {

VNL_CHOLESKY_INSTANTIATE(float);

}  // inline namespace edgetrack_ports
