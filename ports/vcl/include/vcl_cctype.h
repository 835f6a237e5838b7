// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cctype.h: today only the standard <cctype>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cctype_h_
#error "edgetrack's drop-in vcl_cctype.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cctype>

#include "vcl_compiler.h"
