// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_matrix for float (upstream: core/vnl/Templates/).
#include "vnl/vnl_matrix.hxx"

inline namespace edgetrack_ports {

VNL_MATRIX_INSTANTIATE(float);

}  // inline namespace edgetrack_ports
