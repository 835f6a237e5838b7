// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_compiler_detection.h: no longer used upstream; it only forwards to
/// vcl_compiler.h (upstream also prints a note, which we leave out).
#pragma once

#include "vcl_compiler.h"
