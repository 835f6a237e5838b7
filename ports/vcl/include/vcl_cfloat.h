// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cfloat.h: today only the standard <cfloat>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cfloat_h_
#error "edgetrack's drop-in vcl_cfloat.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cfloat>

#include "vcl_compiler.h"
