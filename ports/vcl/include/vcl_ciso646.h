// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ciso646.h: today only the standard <ciso646>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <ciso646>

#include "vcl_compiler.h"
