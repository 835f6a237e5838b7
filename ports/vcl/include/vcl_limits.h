// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_limits.h: today only the standard <limits>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_limits_h_
#error "edgetrack's drop-in vcl_limits.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <limits>

#include "vcl_compiler.h"
