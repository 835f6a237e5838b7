// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_windows_header.h: <windows.h> without min/max macros, on Windows only.
#pragma once

#ifdef __vcl_windows_header_h__
#error "edgetrack's drop-in vcl_windows_header.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#if defined(_WIN32)
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#endif
