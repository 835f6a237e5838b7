// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_numeric.h: today only the standard <numeric>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <numeric>

#include "vcl_compiler.h"
