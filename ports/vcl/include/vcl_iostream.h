// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iostream.h: today only the standard <iostream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <iostream>

#include "vcl_compiler.h"
