// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_valarray.h: today only the standard <valarray>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_valarray_h_
#error "edgetrack's drop-in vcl_valarray.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <valarray>

#include "vcl_compiler.h"
