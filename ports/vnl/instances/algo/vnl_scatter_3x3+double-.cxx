// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_scatter_3x3 for double (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_scatter_3x3.hxx"

inline namespace edgetrack_ports {

VNL_SCATTER_3X3_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
