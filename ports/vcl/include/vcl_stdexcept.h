// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_stdexcept.h: today only the standard <stdexcept>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <stdexcept>

#include "vcl_compiler.h"
