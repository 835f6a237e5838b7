// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cctype.h: today only the standard <cctype>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cctype>

#include "vcl_compiler.h"
