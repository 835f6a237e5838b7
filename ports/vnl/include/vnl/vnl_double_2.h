// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_2.h: vnl_double_2, a fixed vector of 2 doubles.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_double_2 = vnl_vector_fixed<double, 2>;
