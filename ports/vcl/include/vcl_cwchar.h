// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cwchar.h: today only the standard <cwchar>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cwchar>

#include "vcl_compiler.h"
