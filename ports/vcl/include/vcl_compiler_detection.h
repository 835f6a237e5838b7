// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_compiler_detection.h: no longer used upstream; it only forwards to
/// vcl_compiler.h (upstream also prints a note, which we leave out).
#pragma once

#ifdef VXL_COMPILER_DETECTION_H
#error "edgetrack's drop-in vcl_compiler_detection.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vcl_compiler.h"
