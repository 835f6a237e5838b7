// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_exception.h: today only the standard <exception>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_exception_h_
#error "edgetrack's drop-in vcl_exception.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <exception>

#include "vcl_compiler.h"
