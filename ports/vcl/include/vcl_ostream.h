// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ostream.h: today only the standard <ostream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_ostream_h_
#error "edgetrack's drop-in vcl_ostream.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <ostream>

#include "vcl_compiler.h"
