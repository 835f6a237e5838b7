// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_matrix for double (upstream: core/vnl/Templates/).
#include "vnl/vnl_matrix.hxx"

inline namespace edgetrack_ports {

VNL_MATRIX_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
