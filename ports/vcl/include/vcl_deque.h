// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_deque.h: today only the standard <deque>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_deque_h_
#error "edgetrack's drop-in vcl_deque.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <deque>

#include "vcl_compiler.h"
