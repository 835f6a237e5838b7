// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_double_4.h: vnl_double_4, a fixed vector of 4 doubles.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_double_4 = vnl_vector_fixed<double, 4>;
