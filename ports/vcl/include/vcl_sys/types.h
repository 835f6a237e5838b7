// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_sys/types.h: <sys/types.h> (off_t, pid_t, ...).
#pragma once

#ifdef vcl_sys_types_h_
#error "edgetrack's drop-in vcl_sys/types.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <sys/types.h>
