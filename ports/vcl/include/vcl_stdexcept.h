// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_stdexcept.h: today only the standard <stdexcept>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_stdexcept_h_
#error "edgetrack's drop-in vcl_stdexcept.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <stdexcept>

#include "vcl_compiler.h"
