// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_string.h: today only the standard <string>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <string>

#include "vcl_compiler.h"
