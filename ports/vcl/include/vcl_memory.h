// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_memory.h: today only the standard <memory>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_memory_h_
#error "edgetrack's drop-in vcl_memory.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <memory>

#include "vcl_compiler.h"
