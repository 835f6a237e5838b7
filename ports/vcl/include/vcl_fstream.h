// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_fstream.h: today only the standard <fstream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_fstream_h_
#error "edgetrack's drop-in vcl_fstream.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <fstream>

#include "vcl_compiler.h"
