// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iomanip.h: today only the standard <iomanip>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_iomanip_h_
#error "edgetrack's drop-in vcl_iomanip.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iomanip>

#include "vcl_compiler.h"
