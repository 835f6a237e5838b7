// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_map.h: today only the standard <map>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <map>

#include "vcl_compiler.h"
