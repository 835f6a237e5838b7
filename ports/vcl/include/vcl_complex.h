// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_complex.h: today only the standard <complex>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_complex_h_
#error "edgetrack's drop-in vcl_complex.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vcl_compiler.h"
