// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_1x1.h: vnl_float_1x1, a fixed 1 x 1 matrix of floats.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_float_1x1 = vnl_matrix_fixed<float, 1, 1>;
