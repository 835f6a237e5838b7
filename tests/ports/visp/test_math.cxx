// SPDX-License-Identifier: BSD-3-Clause
/// vpMath: angle conversions, rounding halves away from zero, and the sinc family near zero
/// (its series) and away from it (the closed forms), against std:: in double.
#include <cmath>

#include "real/real.h"
#include "real_tolerance.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpMath.h"

// Tolerances at the real's resolution (within_resolution): a product or quotient rounds to
// half an ulp, and an input's own rounding (half an ulp) is amplified by what divides it. So
// rad(180) and rad(deg(x)) hold to 2 ulps; deg(pi/2) carries pi/2's rounding times 180/pi: 32;
// sin x / x has sin's ulp over x plus the quotient's, 1/x + 1 (below 0.1 fixed point takes the
// series, 2); (1 - cos x) / x^2 has cos x's over x^2, 1/x^2 + 2; (1 - sin x / x) / x^2 has
// sin x's over x^3, 1/x^3 + 2.
static void test_math() {
  TEST_NEAR("180 degrees is pi", vpMath::rad(real(180)), M_PI, within_resolution(1e-6, 2));
  TEST_NEAR("pi/2 is 90 degrees", vpMath::deg(real(M_PI / 2)), 90, within_resolution(1e-4, 32));
  TEST_NEAR("rad(deg(x)) = x", vpMath::rad(vpMath::deg(real(0.7))), 0.7, within_resolution(1e-6, 2));
  TEST_EQUAL("round 2.5 -> 3", vpMath::round(real(2.5)), 3);
  TEST_EQUAL("round -2.5 -> -3", vpMath::round(real(-2.5)), -3);
  TEST_EQUAL("round 2.49 -> 2", vpMath::round(real(2.49)), 2);
  TEST_EQUAL("sign", vpMath::sign(real(-0.1)) + vpMath::sign(real(3)) + vpMath::sign(real(0)), 0);
  TEST_NEAR("sqr", vpMath::sqr(real(-3)), 9, 0);
  TEST_EQUAL("maximum", vpMath::maximum(3, 7), 7);
  TEST_EQUAL("minimum", vpMath::minimum(3, 7), 3);
  TEST_EQUAL("modulo of a negative", vpMath::modulo(-1, 5), 4);

  for (double requested : {1e-9, 1e-3, 0.05, 0.09, 0.11, 0.5, 1.0, 2.5}) {
    const real xr = real(requested);
    const double x = static_cast<double>(xr);  // 1e-9 rounds to 0 in fixed point
    const double one_ulp = within_resolution(1e-6, 1), two_ulps = within_resolution(1e-6, 2);
    TEST_NEAR("sinc(x) = sin x / x", vpMath::sinc(xr), x < 1e-3 ? 1 - x * x / 6 : std::sin(x) / x,
              within_resolution(2e-6, x < 0.1 ? 2 : 1 / x + 1));
    TEST_NEAR("mcosc(x) = (1 - cos x) / x^2", vpMath::mcosc(real(std::cos(x)), xr),
              x < 1e-3 ? 0.5 - x * x / 24 : (1 - std::cos(x)) / (x * x),
              x < 1e-3 ? two_ulps : one_ulp / (x * x) + two_ulps);
    TEST_NEAR("msinc(x) = (1 - sin x / x) / x^2", vpMath::msinc(real(std::sin(x)), xr),
              x < 1e-3 ? 1.0 / 6 : (1 - std::sin(x) / x) / (x * x),
              x < 1e-3 ? two_ulps : one_ulp / (x * x * x) + two_ulps);
  }
}

TESTMAIN(test_math)
