// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_stack.h: today only the standard <stack>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_stack_h_
#error "edgetrack's drop-in vcl_stack.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <stack>

#include "vcl_compiler.h"
