// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_svd for double (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_svd.hxx"

inline namespace edgetrack_ports {

VNL_SVD_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
