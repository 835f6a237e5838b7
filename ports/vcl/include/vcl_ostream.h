// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ostream.h: today only the standard <ostream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <ostream>

#include "vcl_compiler.h"
