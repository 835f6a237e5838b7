// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_algorithm.h: today only the standard <algorithm>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_algorithm_h_
#error "edgetrack's drop-in vcl_algorithm.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>

#include "vcl_compiler.h"
