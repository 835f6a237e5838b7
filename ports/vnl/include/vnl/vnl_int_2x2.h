// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_int_2x2.h: vnl_int_2x2, a fixed 2 x 2 matrix of ints.
#pragma once

#include "vnl/vnl_matrix_fixed.h"

using vnl_int_2x2 = vnl_matrix_fixed<int, 2, 2>;
