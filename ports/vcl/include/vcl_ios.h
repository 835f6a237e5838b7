// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ios.h: today only the standard <ios>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_ios_h_
#error "edgetrack's drop-in vcl_ios.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <ios>

#include "vcl_compiler.h"
