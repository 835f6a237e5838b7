// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_matrix for the configured `real` (upstream: core/vnl/Templates/).
#include "real/real.h"
#include "vnl/vnl_matrix.hxx"

VNL_MATRIX_INSTANTIATE(real);
