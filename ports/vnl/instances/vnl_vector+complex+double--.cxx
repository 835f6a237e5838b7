// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for std::complex<double> (upstream: core/vnl/Templates/).
#include <complex>

#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

VNL_VECTOR_INSTANTIATE(std::complex<double>);

}  // inline namespace edgetrack_ports
