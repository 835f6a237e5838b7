// SPDX-License-Identifier: BSD-3-Clause
/// Our helper (no upstream header): the plane rotation shared by the one-sided Jacobi SVD and
/// the Jacobi eigensolver.
#pragma once

#include <cmath>
#include <limits>

#include "vnl/vnl_math.h"

inline namespace edgetrack_ports {

namespace vnl_jacobi {
/// t = tan(theta) of the rotation that zeroes gamma in [alpha gamma; gamma beta]: the root of
/// t^2 + 2 zeta t - 1 = 0 of smaller magnitude, zeta = (beta - alpha) / (2 gamma). For |zeta|
/// past large_zeta = 1/sqrt(eps), t = 1/(2 zeta) to within eps; that branch keeps zeta^2 from
/// overflowing a fixed-point T.
template <class T>
T tangent(const T& alpha, const T& beta, const T& gamma, const T& large_zeta) {
  using std::sqrt;
  const T difference = beta - alpha;
  if (vnl_math::abs(difference) > T(2) * large_zeta * vnl_math::abs(gamma)) return gamma / difference;
  const T zeta = difference / (T(2) * gamma);
  const T t = T(1) / (vnl_math::abs(zeta) + sqrt(T(1) + zeta * zeta));
  return zeta < T(0) ? -t : t;
}

/// The absolute size below which a fixed-point sum of `terms` products is rounding noise
/// (each product rounds to one ulp); zero for floating point, which rounds relatively.
template <class T>
T rounding_floor(unsigned terms) {
  if constexpr (std::numeric_limits<T>::is_iec559) {
    return T(0);
  } else {
    return std::numeric_limits<T>::epsilon() * T(static_cast<int>(terms) + 1);
  }
}

/// The sweep limit; cyclic Jacobi converges quadratically, in well under 20 sweeps.
constexpr int kMaxSweeps = 60;
}  // namespace vnl_jacobi

}  // inline namespace edgetrack_ports
