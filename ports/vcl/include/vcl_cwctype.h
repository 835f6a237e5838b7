// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cwctype.h: today only the standard <cwctype>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cwctype>

#include "vcl_compiler.h"
