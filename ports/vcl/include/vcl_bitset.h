// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_bitset.h: today only the standard <bitset>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_bitset_h_
#error "edgetrack's drop-in vcl_bitset.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <bitset>

#include "vcl_compiler.h"
