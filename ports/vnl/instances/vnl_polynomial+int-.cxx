// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_polynomial for int (upstream: core/vnl/Templates/).
#include "vnl/vnl_polynomial.hxx"

inline namespace edgetrack_ports {

VNL_POLYNOMIAL_INSTANTIATE(int);

}  // inline namespace edgetrack_ports
