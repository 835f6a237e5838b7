// SPDX-License-Identifier: BSD-3-Clause
/// vpMath: angle conversions, rounding halves away from zero, and the sinc family near zero
/// (its series) and away from it (the closed forms), against std:: in double.
#include <cmath>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpMath.h"

static void test_math() {
  TEST_NEAR("180 degrees is pi", vpMath::rad(real(180)), M_PI, 1e-6);
  TEST_NEAR("pi/2 is 90 degrees", vpMath::deg(real(M_PI / 2)), 90, 1e-4);
  TEST_NEAR("rad(deg(x)) = x", vpMath::rad(vpMath::deg(real(0.7))), 0.7, 1e-6);
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
    TEST_NEAR("sinc(x) = sin x / x", vpMath::sinc(xr), x < 1e-3 ? 1 - x * x / 6 : std::sin(x) / x, 2e-6);
    TEST_NEAR("mcosc(x) = (1 - cos x) / x^2", vpMath::mcosc(real(std::cos(x)), xr),
              x < 1e-3 ? 0.5 - x * x / 24 : (1 - std::cos(x)) / (x * x),
              x < 1e-3 ? 1e-6 : 1e-3 * 1e-3 / (x * x) + 1e-6);
    TEST_NEAR("msinc(x) = (1 - sin x / x) / x^2", vpMath::msinc(real(std::sin(x)), xr),
              x < 1e-3 ? 1.0 / 6 : (1 - std::sin(x) / x) / (x * x), x < 1e-3 ? 1e-6 : 1e-6 / (x * x * x) + 1e-6);
  }
}

TESTMAIN(test_math)
