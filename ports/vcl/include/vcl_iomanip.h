// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iomanip.h: today only the standard <iomanip>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <iomanip>

#include "vcl_compiler.h"
