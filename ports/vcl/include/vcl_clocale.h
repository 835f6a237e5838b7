// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_clocale.h: today only the standard <clocale>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_clocale_h_
#error "edgetrack's drop-in vcl_clocale.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <clocale>

#include "vcl_compiler.h"
