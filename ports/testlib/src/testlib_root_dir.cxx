// SPDX-License-Identifier: BSD-3-Clause
// Mirrors VXL's core/testlib/testlib_root_dir.cxx.
#include "testlib/testlib_root_dir.h"

#include <cstdlib>

#include "vcl_where_root_dir.h"

inline namespace edgetrack_ports {

std::string testlib_root_dir() {
  for (const char* variable : {"VXLSRC", "VCLSRC", "VXL_SRC"}) {
    if (const char* value = std::getenv(variable)) return value;
  }
  return VCL_SOURCE_ROOT_DIR;
}

}  // inline namespace edgetrack_ports
