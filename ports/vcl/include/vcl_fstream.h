// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_fstream.h: today only the standard <fstream>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <fstream>

#include "vcl_compiler.h"
