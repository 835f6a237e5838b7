// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstdlib.h: today only the standard <cstdlib>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cstdlib>

#include "vcl_compiler.h"
