// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_complex.h: vnl_math's isnan, isfinite, abs, sqr and
/// squared_magnitude for std::complex (defined with the real forms in vnl_math.h).
#pragma once

#ifdef vnl_complex_h_
#error "edgetrack's drop-in vnl/vnl_complex.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vnl/vnl_math.h"
