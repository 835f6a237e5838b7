// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_2.h: vnl_float_2, a fixed vector of 2 floats.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_float_2 = vnl_vector_fixed<float, 2>;
