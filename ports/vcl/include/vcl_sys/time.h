// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_sys/time.h: <sys/time.h> where the platform has it (gettimeofday).
#pragma once

#if defined(_WIN32)
#include <ctime>
#else
#include <sys/time.h>
#endif
