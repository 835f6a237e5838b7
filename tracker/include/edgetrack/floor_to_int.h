// SPDX-License-Identifier: BSD-3-Clause
/// The whole number at or below a `real`, as an int, without a call to floor where `real` is a
/// floating-point type (x86-64's baseline has no rounding instruction: floor is a library call).
#pragma once

#include <cmath>
#include <type_traits>

#include "real/real.h"

namespace edgetrack {

/// static_cast<int>(floor(x)), under the same precondition (floor(x) is an int): for a float
/// or double the truncation toward zero, one less where that rounded a negative x up, which is
/// exact because |x| < 2^31 truncates to a value of x's type.
inline int floor_to_int(const real& x) {
  if constexpr (std::is_floating_point<real>::value) {
    const int toward_zero = static_cast<int>(x);
    return x < static_cast<real>(toward_zero) ? toward_zero - 1 : toward_zero;
  } else {
    using std::floor;
    return static_cast<int>(floor(x));
  }
}

}  // namespace edgetrack
