// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_set.h: today only the standard <set>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_set_h_
#error "edgetrack's drop-in vcl_set.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <set>

#include "vcl_compiler.h"
