// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/testlib/testlib_root_dir.h: where a test finds the source tree's files.
#pragma once

#include <string>

#define TEST_STR(x) #x
#define TEST_PATH_DEFINE(x) TEST_STR(x)

/// The source tree's root: $VXLSRC, else $VCLSRC, else $VXL_SRC (upstream's order), else the
/// directory CMake configured (vcl_where_root_dir.h).
std::string testlib_root_dir();
