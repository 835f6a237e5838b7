// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_ctime.h: today only the standard <ctime>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <ctime>

#include "vcl_compiler.h"
