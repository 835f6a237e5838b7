// SPDX-License-Identifier: BSD-3-Clause
/// A test tolerance that holds at the configured real's resolution: `base` where the type is
/// finer than that (double, float, S40.23), else `ulps` units of its resolution (S47.16, whose
/// ulp 2^-16 = 1.5e-5 is coarser than most bases). Each caller justifies `ulps` by the roundings
/// its computation has.
#pragma once

#include <algorithm>
#include <limits>

#include "real/real.h"

inline double within_resolution(double base, double ulps) {
  return std::max(base, ulps * static_cast<double>(std::numeric_limits<real>::epsilon()));
}
