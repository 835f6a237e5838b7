// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_list.h: today only the standard <list>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_list_h_
#error "edgetrack's drop-in vcl_list.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <list>

#include "vcl_compiler.h"
