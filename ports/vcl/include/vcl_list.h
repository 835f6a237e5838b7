// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_list.h: today only the standard <list>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <list>

#include "vcl_compiler.h"
