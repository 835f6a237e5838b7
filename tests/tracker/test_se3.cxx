// SPDX-License-Identifier: BSD-3-Clause
/// Se3 properties, for the configured real: log(exp(v)) == v, T * T^-1 == I, vee(hat(w)) == w,
/// and exp agrees with rotating and translating by hand.
#include <cmath>
#include <string>
#include <type_traits>

#include "edgetrack/se3.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// Tolerances named after the type: fixed point carries 2^-16 or 2^-23, double and float more.
double tolerance() {
  const std::string name = real_name();
  if (name == "s47_16") return 2e-3;
  if (name == "s40_23") return 2e-5;
  if (name == "float") return 2e-5;
  return 1e-12;
}

double max_abs_difference(const Mat33& a, const Mat33& b) {
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) worst = std::fmax(worst, std::fabs(static_cast<double>(a.m[i][j] - b.m[i][j])));
  return worst;
}

double max_abs_difference(const Vec3& a, const Vec3& b) {
  return std::fmax(std::fabs(static_cast<double>(a.x - b.x)),
                   std::fmax(std::fabs(static_cast<double>(a.y - b.y)), std::fabs(static_cast<double>(a.z - b.z))));
}

}  // namespace

static void test_se3() {
  const double tol = tolerance();
  const Twist twists[] = {
      {{real(0), real(0), real(0)}, {real(0), real(0), real(0)}},
      {{real(0.01), real(-0.02), real(0.15)}, {real(1e-4), real(-2e-4), real(5e-5)}},
      {{real(0.1), real(0.05), real(0.3)}, {real(0.3), real(-0.2), real(0.5)}},
      {{real(-0.04), real(0.2), real(0.1)}, {real(-1.2), real(0.8), real(1.5)}},
      {{real(0.02), real(0.0), real(0.2)}, {real(0.0), real(3.0), real(0.0)}},
  };
  int k = 0;
  for (const Twist& v : twists) {
    const std::string tag = " (twist " + std::to_string(k++) + ", " + real_name() + ")";
    const Se3 t = Se3::exp(v);
    const Twist back = t.log();
    TEST_NEAR(("log(exp(v)).w == v.w" + tag).c_str(), max_abs_difference(back.w, v.w), 0, tol);
    TEST_NEAR(("log(exp(v)).v == v.v" + tag).c_str(), max_abs_difference(back.v, v.v), 0, tol);
    const Se3 identity = t * t.inverse();
    TEST_NEAR(("T * T^-1 has the identity rotation" + tag).c_str(),
              max_abs_difference(identity.rotation(), Mat33::identity()), 0, tol);
    TEST_NEAR(("T * T^-1 has no translation" + tag).c_str(),
              max_abs_difference(identity.translation(), Vec3{}), 0, tol);
    const Mat33 rtr = t.rotation().transpose() * t.rotation();
    TEST_NEAR(("exp gives an orthonormal rotation" + tag).c_str(), max_abs_difference(rtr, Mat33::identity()), 0,
              tol);
    TEST_NEAR(("vee(hat(w)) == w" + tag).c_str(), max_abs_difference(vee(hat(v.w)), v.w), 0, tol);
  }

  // A quarter turn about z maps x to y, and from_theta_u puts the translation as given.
  const real quarter = real(1.5707963267948966);
  const Se3 turn = Se3::from_theta_u({real(0.01), real(0.02), real(0.03)}, {real(0), real(0), quarter});
  const Vec3 moved = turn * Vec3{real(0.1), real(0), real(0)};
  TEST_NEAR("a quarter turn about z sends x to y, then translates (x)", moved.x, 0.01, tol);
  TEST_NEAR("a quarter turn about z sends x to y, then translates (y)", moved.y, 0.12, tol);
  TEST_NEAR("a quarter turn about z sends x to y, then translates (z)", moved.z, 0.03, tol);
  TEST_NEAR("theta_u of from_theta_u comes back", turn.theta_u().z, static_cast<double>(quarter), tol);

  // retract: a zero step is the pose itself; a step turns on the left and adds the translation.
  const Se3 still = turn.retract(Vec3{}, Vec3{});
  TEST_NEAR("retract(0, 0) keeps the rotation", max_abs_difference(still.rotation(), turn.rotation()), 0, 0);
  TEST_NEAR("retract(0, 0) keeps the translation", max_abs_difference(still.translation(), turn.translation()), 0, 0);
  const Vec3 step{real(0.001), real(-0.002), real(0.003)}, spin{real(0), real(0), -quarter};
  const Se3 stepped = turn.retract(step, spin);
  TEST_NEAR("retract turns on the left: a quarter turn back about z undoes the start's",
            max_abs_difference(stepped.rotation(), Mat33::identity()), 0, tol);
  TEST_NEAR("retract adds the step to the translation", stepped.translation().z, 0.033, tol);

  // same_bits: a copy is the same pose; a different number, or a signed zero, is not.
  const Se3 copy = turn;
  TEST("same_bits holds for a copy", same_bits(copy, turn), true);
  TEST("same_bits fails for a pose one step away", same_bits(stepped, turn), false);
  const Se3 zero(Mat33::identity(), Vec3{real(0), real(0), real(0)});
  const Se3 negative_zero(Mat33::identity(), Vec3{-real(0), real(0), real(0)});
  TEST("same_bits tells signed zeros apart where real has them", same_bits(zero, negative_zero),
       !std::is_floating_point<real>::value);
}

TESTMAIN(test_se3)
