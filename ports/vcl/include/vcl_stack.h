// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_stack.h: today only the standard <stack>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <stack>

#include "vcl_compiler.h"
