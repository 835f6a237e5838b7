// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_functional.h: today only the standard <functional>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_functional_h_
#error "edgetrack's drop-in vcl_functional.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <functional>

#include "vcl_compiler.h"
