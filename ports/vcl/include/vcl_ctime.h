// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ctime.h: today only the standard <ctime>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_ctime_h_
#error "edgetrack's drop-in vcl_ctime.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <ctime>

#include "vcl_compiler.h"
