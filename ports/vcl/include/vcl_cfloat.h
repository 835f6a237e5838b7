// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cfloat.h: today only the standard <cfloat>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cfloat>

#include "vcl_compiler.h"
