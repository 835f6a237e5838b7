// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_cerrno.h: today only the standard <cerrno>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <cerrno>

#include "vcl_compiler.h"
