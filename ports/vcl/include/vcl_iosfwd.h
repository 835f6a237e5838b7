// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iosfwd.h: today only the standard <iosfwd>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <iosfwd>

#include "vcl_compiler.h"
