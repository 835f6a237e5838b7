// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_valarray.h: today only the standard <valarray>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <valarray>

#include "vcl_compiler.h"
