// SPDX-License-Identifier: BSD-3-Clause
/// The math constants some C libraries lack (the paper: Microsoft's had no M_PI, M_PI_2, M_PI_4).
/// Defined only where <cmath> did not define them, so a C library's own values always win.
#pragma once

#ifdef vcl_cmath_h_
#error "edgetrack's drop-in vcl/vcl_cmath.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#ifndef M_PI_2
#define M_PI_2 1.57079632679489661923
#endif
#ifndef M_PI_4
#define M_PI_4 0.78539816339744830962
#endif
