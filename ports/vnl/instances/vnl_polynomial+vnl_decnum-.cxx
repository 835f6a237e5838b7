// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_polynomial for vnl_decnum (upstream: core/vnl/Templates/).
#include "vnl/vnl_decnum.h"
#include "vnl/vnl_decnum_traits.h"
#include "vnl/vnl_polynomial.hxx"

inline namespace edgetrack_ports {

VNL_POLYNOMIAL_INSTANTIATE(vnl_decnum);

}  // inline namespace edgetrack_ports
