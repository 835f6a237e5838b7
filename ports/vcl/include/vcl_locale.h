// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_locale.h: today only the standard <locale>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <locale>

#include "vcl_compiler.h"
