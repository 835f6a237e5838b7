// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_rotation_matrix for the configured `real` (upstream: core/vnl/Templates/).
#include "real/real.h"
#include "vnl/vnl_rotation_matrix.hxx"

inline namespace edgetrack_ports {

VNL_ROTATION_MATRIX_INSTANTIATE(real);

}  // inline namespace edgetrack_ports
