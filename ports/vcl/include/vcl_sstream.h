// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_sstream.h: today only the standard <sstream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <sstream>

#include "vcl_compiler.h"
