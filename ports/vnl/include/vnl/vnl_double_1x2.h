// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_1x2.h: vnl_double_1x2, a fixed 1 x 2 matrix of doubles.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_double_1x2 = vnl_matrix_fixed<double, 1, 2>;
