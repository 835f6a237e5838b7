// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_sparse_matrix for int (upstream: core/vnl/Templates/).
#include "vnl/vnl_sparse_matrix.hxx"

inline namespace edgetrack_ports {

VNL_SPARSE_MATRIX_INSTANTIATE(int);

}  // inline namespace edgetrack_ports
