// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_limits.h: today only the standard <limits>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <limits>

#include "vcl_compiler.h"
