// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_float_4.h: vnl_float_4, a fixed vector of 4 floats.
#pragma once

#include "vnl/vnl_vector_fixed.h"

using vnl_float_4 = vnl_vector_fixed<float, 4>;
