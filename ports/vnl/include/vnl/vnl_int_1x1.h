// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_int_1x1.h: vnl_int_1x1, a fixed 1 x 1 matrix of ints.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_int_1x1 = vnl_matrix_fixed<int, 1, 1>;
