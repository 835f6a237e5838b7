// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_sparse_matrix for float (upstream: core/vnl/Templates/).
#include "vnl/vnl_sparse_matrix.hxx"

inline namespace edgetrack_ports {

VNL_SPARSE_MATRIX_INSTANTIATE(float);

}  // inline namespace edgetrack_ports
