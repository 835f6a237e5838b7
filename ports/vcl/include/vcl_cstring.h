// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstring.h: today only the standard <cstring>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cstring_h_
#error "edgetrack's drop-in vcl_cstring.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstring>

#include "vcl_compiler.h"
