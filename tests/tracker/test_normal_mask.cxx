// SPDX-License-Identifier: BSD-3-Clause
/// normal_mask against the angle route it replaces: alpha = atan2(n_y, n_x), vpMe::maskIndex(alpha)
/// and the sign of the folds, for unit normals all round the circle (with 180 and 90 masks), the
/// four axis normals exactly; away from a half-degree boundary the two must agree.
#include <cmath>

#include "edgetrack/normal_mask.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// The sign a site at normal angle alpha orients its mask with: -1 per fold of the tangent
/// angle alpha + pi/2 into [0, pi], and once more where it rounds to 180 degrees (mask 0).
int sign_by_angle(double alpha) {
  double theta = alpha + M_PI_2;
  int sign = 1;
  if (theta < 0) {
    theta += M_PI;
    sign = -sign;
  }
  if (theta > M_PI) {
    theta -= M_PI;
    sign = -sign;
  }
  if (std::lround(theta * 180 / M_PI) == 180) sign = -sign;
  return sign;
}

/// Degrees from the folded tangent angle of `alpha` to the nearest half-degree boundary.
double to_boundary(double alpha) {
  double degrees = std::fmod((alpha + M_PI_2) * 180 / M_PI + 360, 180.0);
  return std::fabs(degrees - std::floor(degrees) - 0.5);
}

/// Normals every `step` degrees: how many disagree with the angle route more than `margin`
/// degrees from a boundary.
int disagreements(const vpMe& me, double step, double margin) {
  int bad = 0;
  for (double a = -180; a < 180; a += step) {
    const double alpha = a * M_PI / 180;
    const Vec2 normal{real(std::cos(alpha)), real(std::sin(alpha))};
    const real alpha_real = atan2(normal.y, normal.x);
    const NormalMask mask = normal_mask(me, normal);
    if (to_boundary(alpha) < margin) continue;
    if (mask.index != me.maskIndex(alpha_real) || mask.sign != sign_by_angle(static_cast<double>(alpha_real))) ++bad;
  }
  return bad;
}

}  // namespace

void test_normal_mask() {
  vpMe me;
  TEST_EQUAL("180 masks: as the angle route round the circle", disagreements(me, 0.0173, 1e-3), 0);
  for (const Vec2& n : {Vec2{real(1), real(0)}, Vec2{real(0), real(1)}, Vec2{real(-1), real(0)}, Vec2{real(0), real(-1)}}) {
    const real alpha = atan2(n.y, n.x);
    const NormalMask mask = normal_mask(me, n);
    TEST_EQUAL("an axis normal: the angle route's mask", mask.index, me.maskIndex(alpha));
    TEST_EQUAL("and sign", mask.sign, sign_by_angle(static_cast<double>(alpha)));
  }
  TEST_EQUAL("normal (0, 1): tangent 180 degrees is mask 0", normal_mask(me, Vec2{real(0), real(1)}).index, 0u);
  TEST_EQUAL("turned over", normal_mask(me, Vec2{real(0), real(1)}).sign, -1);
  me.setMaskNumber(90);
  TEST_EQUAL("90 masks (2 degrees each): as the angle route", disagreements(me, 0.0311, 1e-3), 0);
}

TESTMAIN(test_normal_mask)
