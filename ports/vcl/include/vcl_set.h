// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_set.h: today only the standard <set>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <set>

#include "vcl_compiler.h"
