// SPDX-License-Identifier: BSD-3-Clause
#include "vcl_deprecated.h"

#include <cstdio>

#include "vcl/vcl_compiler.h"

inline namespace edgetrack_ports {

void vcl_deprecated_warn(const char* func_name) {
  std::fprintf(stderr, "deprecated function %s called\n", func_name ? func_name : "(unnamed)");
}

void vcl_deprecated_abort(const char* func_name) {
  vcl_deprecated_warn(func_name);
  vcl_abort("deprecated function called");
}

}  // inline namespace edgetrack_ports
