// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstring.h: today only the standard <cstring>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cstring>

#include "vcl_compiler.h"
