// SPDX-License-Identifier: BSD-3-Clause
/// The mask of a site from its normal: a binary search of the half-degree boundaries.
#include "edgetrack/normal_mask.h"

#include <cstdint>
#include <type_traits>

#include "edgetrack/angles.h"

namespace edgetrack {

namespace {

/// 2^30: the integer scale of unit vectors here (products of two fit in 62 bits).
constexpr double kUnit = 1073741824.0;

/// sin x or cos x for x in [0, pi] by their series, at compile time only: the table below holds
/// integers, so no floating point runs on a core without an FPU.
constexpr double series(double x, bool cosine) {
  double term = cosine ? 1.0 : x, sum = term;
  for (int n = cosine ? 1 : 2; n < 60; n += 2) {
    term *= -x * x / (n * (n + 1.0));
    sum += term;
  }
  return sum;
}

constexpr std::int32_t table_unit(double v) { return static_cast<std::int32_t>(v * kUnit + (v < 0 ? -0.5 : 0.5)); }

/// Direction (k + 0.5) degrees, k = 0..179: where the tangent angle rounds up to k + 1 degrees.
struct Boundaries {
  std::int32_t cos[180];
  std::int32_t sin[180];
};

constexpr Boundaries make_boundaries() {
  Boundaries b{};
  for (int k = 0; k < 180; ++k) {
    const double angle = (k + 0.5) * kPi / 180;
    b.cos[k] = table_unit(series(angle, true));
    b.sin[k] = table_unit(series(angle, false));
  }
  return b;
}

constexpr Boundaries kBoundaries = make_boundaries();

/// x (|x| <= 1) times 2^30, truncated; a shift of the raw value in the fixed-point builds.
template <class Real>
std::int32_t unit_integer(const Real& x) {
  if constexpr (std::is_floating_point<Real>::value) {
    return static_cast<std::int32_t>(x * Real(kUnit));
  } else {
    static_assert(Real::kFractionBits <= 30, "a unit fits 2^30");
    return static_cast<std::int32_t>(x.raw() * (std::int64_t(1) << (30 - Real::kFractionBits)));
  }
}

}  // namespace

NormalMask normal_mask(const vpMe& me, const Vec2& normal) {
  // The tangent at alpha + pi/2 is (-n_y, n_x); folded into [0, pi] (y >= 0) when n_x < 0.
  const std::int32_t nx = unit_integer(normal.x), ny = unit_integer(normal.y);
  NormalMask mask;
  std::int32_t tx = -ny, ty = nx;
  if (nx < 0) {
    tx = ny;
    ty = -nx;
    mask.sign = -1;
  }
  // Whole degrees, rounded half up: the number of boundaries at or below the tangent's angle.
  int degrees = 0, above = 180;
  while (degrees < above) {
    const int mid = (degrees + above) >> 1;
    const std::int64_t cross = std::int64_t(kBoundaries.cos[mid]) * ty - std::int64_t(kBoundaries.sin[mid]) * tx;
    if (cross >= 0)
      degrees = mid + 1;
    else
      above = mid;
  }
  if (degrees == 180) {
    degrees = 0;
    mask.sign = -mask.sign;
  }
  const unsigned int step = me.getAngleStep();
  const unsigned int index = step > 1 ? static_cast<unsigned int>(degrees) / step : static_cast<unsigned int>(degrees);
  mask.index = index < me.getMaskNumber() ? index : me.getMaskNumber() - 1;
  return mask;
}

}  // namespace edgetrack
