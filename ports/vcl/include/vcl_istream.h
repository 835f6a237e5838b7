// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_istream.h: today only the standard <istream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_istream_h_
#error "edgetrack's drop-in vcl_istream.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <istream>

#include "vcl_compiler.h"
