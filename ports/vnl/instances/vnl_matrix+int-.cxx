// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_matrix for int (upstream: core/vnl/Templates/).
#include "vnl/vnl_matrix.hxx"

inline namespace edgetrack_ports {

VNL_MATRIX_INSTANTIATE(int);

}  // inline namespace edgetrack_ports
