// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_svd for float (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_svd.hxx"

inline namespace edgetrack_ports {

VNL_SVD_INSTANTIATE(float);

}  // inline namespace edgetrack_ports
