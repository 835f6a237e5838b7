// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cassert.h: today only the standard <cassert>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cassert_h_
#error "edgetrack's drop-in vcl_cassert.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vcl_compiler.h"
