// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_least_squares_function_of for the configured `real`.
#include "real/real.h"
#include "vnl/vnl_least_squares_function.hxx"

VNL_LEAST_SQUARES_FUNCTION_INSTANTIATE(real);
