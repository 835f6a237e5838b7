// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_2x2.h: vnl_float_2x2, a fixed 2 x 2 matrix of floats.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_float_2x2 = vnl_matrix_fixed<float, 2, 2>;
