// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for vnl_rational (upstream: core/vnl/Templates/).
#include "vnl/vnl_rational.h"
#include "vnl/vnl_rational_traits.h"
#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

VNL_VECTOR_INSTANTIATE(vnl_rational);

}  // inline namespace edgetrack_ports
