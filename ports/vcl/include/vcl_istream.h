// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_istream.h: today only the standard <istream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <istream>

#include "vcl_compiler.h"
