// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_matrix for vnl_rational (upstream: core/vnl/Templates/).
#include "vnl/vnl_rational.h"
#include "vnl/vnl_rational_traits.h"
#include "vnl/vnl_matrix.hxx"

inline namespace edgetrack_ports {

VNL_MATRIX_INSTANTIATE(vnl_rational);

}  // inline namespace edgetrack_ports
