// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_exception.h: today only the standard <exception>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <exception>

#include "vcl_compiler.h"
