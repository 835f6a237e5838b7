// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_int_3.h: vnl_int_3, a fixed vector of 3 ints.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_int_3 = vnl_vector_fixed<int, 3>;
