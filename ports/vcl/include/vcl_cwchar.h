// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cwchar.h: today only the standard <cwchar>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cwchar_h_
#error "edgetrack's drop-in vcl_cwchar.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cwchar>

#include "vcl_compiler.h"
