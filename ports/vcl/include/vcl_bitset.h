// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_bitset.h: today only the standard <bitset>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <bitset>

#include "vcl_compiler.h"
