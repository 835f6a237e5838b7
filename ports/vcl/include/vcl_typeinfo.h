// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_typeinfo.h: today only the standard <typeinfo>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_typeinfo_h_
#error "edgetrack's drop-in vcl_typeinfo.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <typeinfo>

#include "vcl_compiler.h"
