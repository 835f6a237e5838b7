// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_utility.h: today only the standard <utility>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_utility_h_
#error "edgetrack's drop-in vcl_utility.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <utility>

#include "vcl_compiler.h"
