// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_3.h: vnl_float_3, a fixed vector of 3 floats.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_float_3 = vnl_vector_fixed<float, 3>;
