// SPDX-License-Identifier: BSD-3-Clause
/// Metres to millimetres, the pose step's length unit. The pose solve (pose_solver.cpp) and the
/// pose uncertainty work in millimetres (the translation parameters and the camera-frame
/// points): in metres the Jacobian's translation columns are px / Z ~ 1500 px/m, past the 512
/// below which S40.23's multiply is one 32 x 32-bit product (real/fixed64.h), both in the
/// Jacobian and in MINPACK's QR of it; in millimetres they are ~1.5 px/mm. MINPACK scales each
/// column by its norm, so in exact arithmetic the steps do not depend on the unit.
#pragma once

#include "edgetrack/geometry.h"

namespace edgetrack {

constexpr int kMillimetresPerMetre = 1000;

/// 1000 x, exactly as real(1000) * x rounds it, as products by 8 and by 125: S40.23's fast
/// multiply takes operands below 256 (real/fixed64.h), which 1000 is not.
inline real to_millimetres(const real& metres) { return real(125) * (real(8) * metres); }
inline Vec3 to_millimetres(const Vec3& metres) {
  return {to_millimetres(metres.x), to_millimetres(metres.y), to_millimetres(metres.z)};
}

}  // namespace edgetrack
