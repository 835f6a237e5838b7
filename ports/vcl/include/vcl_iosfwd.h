// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iosfwd.h: today only the standard <iosfwd>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_iosfwd_h_
#error "edgetrack's drop-in vcl_iosfwd.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

#include "vcl_compiler.h"
