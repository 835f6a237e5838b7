// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_functional.h: today only the standard <functional>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <functional>

#include "vcl_compiler.h"
