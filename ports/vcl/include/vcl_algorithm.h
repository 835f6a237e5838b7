// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_algorithm.h: today only the standard <algorithm>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <algorithm>

#include "vcl_compiler.h"
