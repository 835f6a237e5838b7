// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_matrix for std::complex<double> (upstream: core/vnl/Templates/).
#include <complex>

#include "vnl/vnl_matrix.hxx"

VNL_MATRIX_INSTANTIATE(std::complex<double>);
