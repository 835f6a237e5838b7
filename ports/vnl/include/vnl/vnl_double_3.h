// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_3.h: vnl_double_3, a fixed vector of 3 doubles.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_double_3 = vnl_vector_fixed<double, 3>;
