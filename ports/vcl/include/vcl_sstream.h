// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_sstream.h: today only the standard <sstream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_sstream_h_
#error "edgetrack's drop-in vcl_sstream.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <sstream>

#include "vcl_compiler.h"
