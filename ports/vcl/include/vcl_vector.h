// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_vector.h: today only the standard <vector>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_vector_h_
#error "edgetrack's drop-in vcl_vector.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <vector>

#include "vcl_compiler.h"
