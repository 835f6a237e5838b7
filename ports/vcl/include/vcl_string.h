// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_string.h: today only the standard <string>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_string_h_
#error "edgetrack's drop-in vcl_string.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <string>

#include "vcl_compiler.h"
