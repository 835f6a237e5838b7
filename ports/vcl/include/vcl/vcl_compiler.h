// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors the part of VXL's vcl that the paper had to touch: abort, time and math constants.
/// On a platform without abort() (the paper's Windows Mobile), define VCL_NO_ABORT: vcl_abort()
/// then reports the failure and ends the process with a failure status instead.
#pragma once

#include <ctime>

inline namespace edgetrack_ports {

/// Reports `what` on stderr and stops the process (abort(), or exit status 134 with VCL_NO_ABORT).
[[noreturn]] void vcl_abort(const char* what);

/// time() where the C library has it; otherwise seconds since the epoch from std::chrono.
std::time_t vcl_time(std::time_t* out);

}  // inline namespace edgetrack_ports
