// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_climits.h: today only the standard <climits>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_climits_h_
#error "edgetrack's drop-in vcl_climits.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <climits>

#include "vcl_compiler.h"
