// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_block.h"

#include <cstdio>

#include "vcl/vcl_compiler.h"

inline namespace edgetrack_ports {

void vnl_block_raise_exception(const char* file, int line, const char* why) {
  std::fprintf(stderr, "%s:%d: vnl_block: %s\n", file, line, why);
  vcl_abort(why);
}

}  // inline namespace edgetrack_ports
