// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iterator.h: today only the standard <iterator>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <iterator>

#include "vcl_compiler.h"
