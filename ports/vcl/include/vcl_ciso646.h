// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ciso646.h: today only the standard <ciso646>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_ciso646_h_
#error "edgetrack's drop-in vcl_ciso646.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <ciso646>

#include "vcl_compiler.h"
