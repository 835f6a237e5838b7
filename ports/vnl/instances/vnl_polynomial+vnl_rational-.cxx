// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_polynomial for vnl_rational (upstream: core/vnl/Templates/).
#include "vnl/vnl_rational.h"
#include "vnl/vnl_polynomial.hxx"

inline namespace edgetrack_ports {

VNL_POLYNOMIAL_INSTANTIATE(vnl_rational);

}  // inline namespace edgetrack_ports
