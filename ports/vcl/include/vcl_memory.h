// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_memory.h: today only the standard <memory>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <memory>

#include "vcl_compiler.h"
