// SPDX-License-Identifier: BSD-3-Clause
/// vpMath's sinc family. Near zero each is its Taylor series: in double below upstream's
/// thresholds (1e-8, 2.5e-4), where upstream returns the limit; in fixed point below 0.1 rad,
/// with the x^2 term (the next term, under x^4 / 720, is below the type's resolution).
#include "visp3/core/vpMath.h"

#include <cmath>
#include <type_traits>

inline namespace edgetrack_ports {

namespace {
constexpr bool kFloating = std::is_floating_point<real>::value;
const real kSincLimit = kFloating ? real(1e-8) : real(0.1);
const real kCoscLimit = kFloating ? real(2.5e-4) : real(0.1);
}  // namespace

real vpMath::sinc(real x) {
  using std::sin;
  if (abs(x) < kSincLimit) return real(1) - x * x / 6;
  return sin(x) / x;
}

real vpMath::sinc(real sinx, real x) {
  if (abs(x) < kSincLimit) return real(1) - x * x / 6;
  return sinx / x;
}

real vpMath::mcosc(real cosx, real x) {
  if (abs(x) < kCoscLimit) return real(0.5) - x * x / 24;
  return (real(1) - cosx) / x / x;
}

real vpMath::msinc(real sinx, real x) {
  if (abs(x) < kCoscLimit) return real(1) / 6 - x * x / 120;
  return (real(1) - sinx / x) / x / x;
}

}  // inline namespace edgetrack_ports
