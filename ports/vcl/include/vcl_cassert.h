// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cassert.h: today only the standard <cassert>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cassert>

#include "vcl_compiler.h"
