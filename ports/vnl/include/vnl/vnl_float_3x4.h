// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_3x4.h: vnl_float_3x4, a fixed 3 x 4 matrix of floats.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_float_3x4 = vnl_matrix_fixed<float, 3, 4>;
