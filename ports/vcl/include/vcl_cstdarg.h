// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstdarg.h: today only the standard <cstdarg>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cstdarg_h_
#error "edgetrack's drop-in vcl_cstdarg.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdarg>

#include "vcl_compiler.h"
