// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cmath.h: the standard <cmath>, plus the M_PI family where the C library
/// lacks it (vcl/vcl_cmath.h, the paper's Windows Mobile fix).
#pragma once

#ifdef vcl_cmath_h_
#error "edgetrack's drop-in vcl_cmath.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>

#include "vcl/vcl_cmath.h"
#include "vcl_compiler.h"
