// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_climits.h: today only the standard <climits>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <climits>

#include "vcl_compiler.h"
