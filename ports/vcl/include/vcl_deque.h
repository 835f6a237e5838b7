// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_deque.h: today only the standard <deque>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <deque>

#include "vcl_compiler.h"
