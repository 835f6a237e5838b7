// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for int (upstream: core/vnl/Templates/).
#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

VNL_VECTOR_INSTANTIATE(int);

}  // inline namespace edgetrack_ports
