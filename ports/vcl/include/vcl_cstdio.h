// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cstdio.h: today only the standard <cstdio>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cstdio>

#include "vcl_compiler.h"
