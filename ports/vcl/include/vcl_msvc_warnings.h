// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_msvc_warnings.h: silences MSVC warnings; nothing to do elsewhere.
#pragma once

#if defined(_MSC_VER)
#pragma warning(disable : 4996)  // "unsafe" C library functions
#endif
