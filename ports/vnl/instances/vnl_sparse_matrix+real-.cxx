// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_sparse_matrix for the configured `real` when it is fixed point (a double or float
/// `real` is already instantiated by the double and float files; upstream: core/vnl/Templates/).
#include "real/real.h"
#include "vnl/vnl_sparse_matrix.hxx"

#if !defined(EDGETRACK_REAL_DOUBLE) && !defined(EDGETRACK_REAL_FLOAT)
inline namespace edgetrack_ports {

VNL_SPARSE_MATRIX_INSTANTIATE(real);
}  // inline namespace edgetrack_ports
#endif
