// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_matrix for std::complex<float> (upstream: core/vnl/Templates/).
#include <complex>

#include "vnl/vnl_matrix.hxx"

inline namespace edgetrack_ports {

VNL_MATRIX_INSTANTIATE(std::complex<float>);

}  // inline namespace edgetrack_ports
