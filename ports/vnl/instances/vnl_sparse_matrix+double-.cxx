// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_sparse_matrix for double (upstream: core/vnl/Templates/).
#include "vnl/vnl_sparse_matrix.hxx"

VNL_SPARSE_MATRIX_INSTANTIATE(double);
