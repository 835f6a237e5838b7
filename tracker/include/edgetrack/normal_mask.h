// SPDX-License-Identifier: BSD-3-Clause
/// Which of vpMe's oriented masks a moving-edge site uses, and with which sign, found from the
/// control point's unit normal itself rather than from its angle.
#pragma once

#include "edgetrack/geometry.h"
#include "visp3/me/vpMe.h"

namespace edgetrack {

/// A site's mask: vpMe mask `index`, its response times `sign` (+1 or -1).
struct NormalMask {
  unsigned int index = 0;
  int sign = 1;
};

/// The mask and sign a vpMeSite at normal angle alpha = atan2(normal.y, normal.x) uses:
/// vpMe::maskIndex(alpha), which folds the tangent angle alpha + pi/2 into [0, pi] and rounds it
/// to whole degrees (180 is mask 0), and the sign that orients the mask along the normal (each
/// fold by pi, and the move from 180 degrees to mask 0, turn it over). Without an arctangent: the
/// folded tangent is compared with the half-degree boundaries by cross products in integers, so
/// the result differs from the angle's only where the angle lies within about 1e-9 rad of a
/// boundary, and is the same in every `real` build. `normal` must be a unit vector.
NormalMask normal_mask(const vpMe& me, const Vec2& normal);

}  // namespace edgetrack
