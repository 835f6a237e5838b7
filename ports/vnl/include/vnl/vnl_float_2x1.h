// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_2x1.h: vnl_float_2x1, a fixed 2 x 1 matrix of floats.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_float_2x1 = vnl_matrix_fixed<float, 2, 1>;
