// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_clocale.h: today only the standard <clocale>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <clocale>

#include "vcl_compiler.h"
