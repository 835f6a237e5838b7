// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstddef.h: today only the standard <cstddef>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cstddef>

#include "vcl_compiler.h"
