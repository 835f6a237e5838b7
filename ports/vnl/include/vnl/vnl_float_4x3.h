// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_4x3.h: vnl_float_4x3, a fixed 4 x 3 matrix of floats.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_float_4x3 = vnl_matrix_fixed<float, 4, 3>;
