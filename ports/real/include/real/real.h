// SPDX-License-Identifier: BSD-3-Clause
/// The one scalar type that ports/ and tracker/ compute with (the paper's section 3.3).
/// CMake's EDGETRACK_REAL picks it; everything else is written against `real`.
#pragma once

#include "real/fixed64.h"
#include "real/real_config.h"

#if defined(EDGETRACK_REAL_DOUBLE)
using real = double;
#elif defined(EDGETRACK_REAL_FLOAT)
using real = float;
#elif defined(EDGETRACK_REAL_S47_16)
using real = fixedpoint::s47_16;
#elif defined(EDGETRACK_REAL_S40_23)
using real = fixedpoint::s40_23;
#else
#error "real_config.h names no known EDGETRACK_REAL"
#endif

/// Name of the configured type, for reports ("double", "s40_23", ...).
constexpr const char* real_name() { return EDGETRACK_REAL_NAME; }
