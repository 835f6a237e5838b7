// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_complex.h: today only the standard <complex>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <complex>

#include "vcl_compiler.h"
