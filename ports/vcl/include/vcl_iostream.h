// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iostream.h: today only the standard <iostream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_iostream_h_
#error "edgetrack's drop-in vcl_iostream.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iostream>

#include "vcl_compiler.h"
