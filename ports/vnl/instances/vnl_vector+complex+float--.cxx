// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for std::complex<float> (upstream: core/vnl/Templates/).
#include <complex>

#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

VNL_VECTOR_INSTANTIATE(std::complex<float>);

}  // inline namespace edgetrack_ports
