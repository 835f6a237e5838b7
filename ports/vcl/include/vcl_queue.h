// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_queue.h: today only the standard <queue>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_queue_h_
#error "edgetrack's drop-in vcl_queue.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <queue>

#include "vcl_compiler.h"
