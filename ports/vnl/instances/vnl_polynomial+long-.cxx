// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_polynomial for long (upstream: core/vnl/Templates/).
#include "vnl/vnl_polynomial.hxx"

inline namespace edgetrack_ports {

VNL_POLYNOMIAL_INSTANTIATE(long);

}  // inline namespace edgetrack_ports
