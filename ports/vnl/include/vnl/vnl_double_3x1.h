// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_3x1.h: vnl_double_3x1, a fixed 3 x 1 matrix of doubles.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_double_3x1 = vnl_matrix_fixed<double, 3, 1>;
