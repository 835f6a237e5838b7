// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_streambuf.h: today only the standard <streambuf>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_streambuf_h_
#error "edgetrack's drop-in vcl_streambuf.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <streambuf>

#include "vcl_compiler.h"
