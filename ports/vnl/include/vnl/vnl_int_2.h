// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_int_2.h: vnl_int_2, a fixed vector of 2 ints.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_int_2 = vnl_vector_fixed<int, 2>;
