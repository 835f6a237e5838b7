// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_vector.h: today only the standard <vector>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <vector>

#include "vcl_compiler.h"
