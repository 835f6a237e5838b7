// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_csetjmp.h: today only the standard <csetjmp>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_csetjmp_h_
#error "edgetrack's drop-in vcl_csetjmp.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <csetjmp>

#include "vcl_compiler.h"
