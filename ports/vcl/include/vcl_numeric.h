// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_numeric.h: today only the standard <numeric>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_numeric_h_
#error "edgetrack's drop-in vcl_numeric.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <numeric>

#include "vcl_compiler.h"
