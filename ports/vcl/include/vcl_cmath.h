// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cmath.h: the standard <cmath>, plus the M_PI family where the C library
/// lacks it (vcl/vcl_cmath.h, the paper's Windows Mobile fix).
#pragma once

#include <cmath>

#include "vcl/vcl_cmath.h"
#include "vcl_compiler.h"
