// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_sys/types.h: <sys/types.h> (off_t, pid_t, ...).
#pragma once

#include <sys/types.h>
