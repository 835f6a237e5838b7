// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstdarg.h: today only the standard <cstdarg>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cstdarg>

#include "vcl_compiler.h"
