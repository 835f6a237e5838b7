// SPDX-License-Identifier: BSD-3-Clause
#include "vcl/vcl_compiler.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

inline namespace edgetrack_ports {

void vcl_abort(const char* what) {
  std::fprintf(stderr, "vcl_abort: %s\n", what ? what : "(no reason given)");
  std::fflush(stderr);
#ifdef VCL_NO_ABORT
  std::_Exit(134);  // the status abort() would have given, without raising SIGABRT
#else
  std::abort();
#endif
}

std::time_t vcl_time(std::time_t* out) {
#ifdef VCL_NO_TIME
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  const auto seconds = static_cast<std::time_t>(std::chrono::duration_cast<std::chrono::seconds>(now).count());
#else
  const std::time_t seconds = std::time(nullptr);
#endif
  if (out) *out = seconds;
  return seconds;
}

}  // inline namespace edgetrack_ports
