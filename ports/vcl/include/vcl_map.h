// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_map.h: today only the standard <map>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_map_h_
#error "edgetrack's drop-in vcl_map.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <map>

#include "vcl_compiler.h"
