// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cwctype.h: today only the standard <cwctype>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cwctype_h_
#error "edgetrack's drop-in vcl_cwctype.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cwctype>

#include "vcl_compiler.h"
