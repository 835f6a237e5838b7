// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_sparse_matrix for std::complex<double> (upstream: core/vnl/Templates/).
#include <complex>

#include "vnl/vnl_sparse_matrix.hxx"

inline namespace edgetrack_ports {

VNL_SPARSE_MATRIX_INSTANTIATE(std::complex<double>);

}  // inline namespace edgetrack_ports
