// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_streambuf.h: today only the standard <streambuf>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <streambuf>

#include "vcl_compiler.h"
