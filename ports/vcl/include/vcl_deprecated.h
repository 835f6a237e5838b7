// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_deprecated.h: VXL_DEPRECATED_MACRO(name) marks a call to a deprecated
/// function. With VXL_WARN_DEPRECATED it reports the call on stderr (every time, or only the
/// first time with VXL_WARN_DEPRECATED_ONCE); with VXL_WARN_DEPRECATED_ABORT it also aborts.
#pragma once

#ifdef vcl_deprecated_h_
#error "edgetrack's drop-in vcl_deprecated.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vcl_compiler.h"

inline namespace edgetrack_ports {

/// Prints "deprecated function <name> called" on stderr.
void vcl_deprecated_warn(const char* func_name);
/// Prints the same line, then calls vcl_abort.
void vcl_deprecated_abort(const char* func_name);

#if defined(VXL_WARN_DEPRECATED_ABORT)
#define VXL_DEPRECATED_MACRO(f) vcl_deprecated_abort(f)
#elif defined(VXL_WARN_DEPRECATED_ONCE)
#define VXL_DEPRECATED_MACRO(f)             \
  do {                                      \
    static bool vcl_deprecated_first = true; \
    if (vcl_deprecated_first) {             \
      vcl_deprecated_warn(f);               \
      vcl_deprecated_first = false;         \
    }                                       \
  } while (false)
#elif defined(VXL_WARN_DEPRECATED)
#define VXL_DEPRECATED_MACRO(f) vcl_deprecated_warn(f)
#else
#define VXL_DEPRECATED_MACRO(f) /* deprecation is silent */
#endif

}  // inline namespace edgetrack_ports
