// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_locale.h: today only the standard <locale>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_locale_h_
#error "edgetrack's drop-in vcl_locale.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <locale>

#include "vcl_compiler.h"
