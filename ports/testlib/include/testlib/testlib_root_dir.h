// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/testlib/testlib_root_dir.h: where a test finds the source tree's files.
#pragma once

#ifdef testlib_root_dir_h_
#error "edgetrack's drop-in testlib/testlib_root_dir.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <string>

#define TEST_STR(x) #x
#define TEST_PATH_DEFINE(x) TEST_STR(x)

inline namespace edgetrack_ports {

/// The source tree's root: $VXLSRC, else $VCLSRC, else $VXL_SRC (upstream's order), else the
/// directory CMake configured (vcl_where_root_dir.h).
std::string testlib_root_dir();

}  // inline namespace edgetrack_ports
