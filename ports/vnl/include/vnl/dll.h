// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/dll.h: the export macro for a shared vnl library; our vnl is
/// static, so it expands to nothing.
#pragma once

#ifdef vnl_dll_h_
#error "edgetrack's drop-in vnl/dll.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#define VNL_DLL_DATA
#ifndef VNL_EXPORT
#define VNL_EXPORT
#endif
