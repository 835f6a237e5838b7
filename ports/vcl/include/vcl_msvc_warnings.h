// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_msvc_warnings.h: silences MSVC warnings; nothing to do elsewhere.
#pragma once

#ifdef vcl_msvc_warnings_h__
#error "edgetrack's drop-in vcl_msvc_warnings.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#if defined(_MSC_VER)
#pragma warning(disable : 4996)  // "unsafe" C library functions
#endif
