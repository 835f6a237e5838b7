// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for float (upstream: core/vnl/Templates/).
#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

VNL_VECTOR_INSTANTIATE(float);

}  // inline namespace edgetrack_ports
