// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_csignal.h: today only the standard <csignal>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#ifdef vcl_csignal_h_
#error "edgetrack's drop-in vcl_csignal.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <csignal>

#include "vcl_compiler.h"
