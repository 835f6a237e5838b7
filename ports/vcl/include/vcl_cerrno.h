// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cerrno.h: today only the standard <cerrno>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_cerrno_h_
#error "edgetrack's drop-in vcl_cerrno.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cerrno>

#include "vcl_compiler.h"
