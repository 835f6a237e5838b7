// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_sys/time.h: <sys/time.h> where the platform has it (gettimeofday).
#pragma once

#ifdef vcl_sys_time_h_
#error "edgetrack's drop-in vcl_sys/time.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#if defined(_WIN32)
#include <ctime>
#else
#include <sys/time.h>
#endif
