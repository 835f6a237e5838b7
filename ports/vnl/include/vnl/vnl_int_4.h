// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_int_4.h: vnl_int_4, a fixed vector of 4 ints.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_int_4 = vnl_vector_fixed<int, 4>;
