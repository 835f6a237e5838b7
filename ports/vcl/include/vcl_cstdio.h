// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstdio.h: today only the standard <cstdio>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cstdio_h_
#error "edgetrack's drop-in vcl_cstdio.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdio>

#include "vcl_compiler.h"
