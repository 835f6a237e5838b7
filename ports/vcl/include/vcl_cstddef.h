// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstddef.h: today only the standard <cstddef>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cstddef_h_
#error "edgetrack's drop-in vcl_cstddef.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>

#include "vcl_compiler.h"
