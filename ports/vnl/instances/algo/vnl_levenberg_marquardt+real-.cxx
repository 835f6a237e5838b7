// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_levenberg_marquardt_of for the configured `real`.
#include "real/real.h"
#include "vnl/algo/vnl_levenberg_marquardt.hxx"

VNL_LEVENBERG_MARQUARDT_INSTANTIATE(real);
