// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for the configured `real` (upstream: core/vnl/Templates/).
#include "real/real.h"
#include "vnl/vnl_vector.hxx"

VNL_VECTOR_INSTANTIATE(real);
