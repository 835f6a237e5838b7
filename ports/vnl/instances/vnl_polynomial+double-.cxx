// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_polynomial for double (upstream: core/vnl/Templates/).
#include "vnl/vnl_polynomial.hxx"

inline namespace edgetrack_ports {

VNL_POLYNOMIAL_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
