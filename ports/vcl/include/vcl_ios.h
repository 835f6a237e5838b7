// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ios.h: today only the standard <ios>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <ios>

#include "vcl_compiler.h"
