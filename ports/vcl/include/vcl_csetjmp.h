// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_csetjmp.h: today only the standard <csetjmp>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <csetjmp>

#include "vcl_compiler.h"
