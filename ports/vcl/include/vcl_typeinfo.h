// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_typeinfo.h: today only the standard <typeinfo>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <typeinfo>

#include "vcl_compiler.h"
