// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_utility.h: today only the standard <utility>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <utility>

#include "vcl_compiler.h"
