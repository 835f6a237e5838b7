// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_complex.h: vnl_math's isnan, isfinite, abs, sqr and
/// squared_magnitude for std::complex (defined with the real forms in vnl_math.h).
#pragma once

#include <complex>

#include "vnl/vnl_math.h"
