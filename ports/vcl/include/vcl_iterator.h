// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iterator.h: today only the standard <iterator>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_iterator_h_
#error "edgetrack's drop-in vcl_iterator.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iterator>

#include "vcl_compiler.h"
