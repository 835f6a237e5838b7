// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_queue.h: today only the standard <queue>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <queue>

#include "vcl_compiler.h"
