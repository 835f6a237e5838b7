// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstdlib.h: today only the standard <cstdlib>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cstdlib_h_
#error "edgetrack's drop-in vcl_cstdlib.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdlib>

#include "vcl_compiler.h"
