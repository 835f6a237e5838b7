// SPDX-License-Identifier: BSD-3-Clause
// vnl_math's constants have upstream's values, and its helpers give the textbook results, for
// every scalar (the constants as T are compile-time conversions).
#include <cmath>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_math.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckMath {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double half_ulp = ulps<T>(0.5);
    TEST_NEAR("constant<T>::pi is pi to half an ulp" + in, vnl_math::constant<T>::pi, std::acos(-1.0),
              std::acos(-1.0) * half_ulp);
    TEST_NEAR("constant<T>::pi_over_2" + in, vnl_math::constant<T>::pi_over_2, std::acos(-1.0) / 2, half_ulp);
    TEST_NEAR("constant<T>::pi_over_4" + in, vnl_math::constant<T>::pi_over_4, std::acos(-1.0) / 4, half_ulp);
    TEST_NEAR("constant<T>::sqrt1_2" + in, vnl_math::constant<T>::sqrt1_2, std::sqrt(0.5), half_ulp);
    TEST_NEAR("constant<T>::deg_per_rad" + in, vnl_math::constant<T>::deg_per_rad, 180 / std::acos(-1.0),
              60 * half_ulp);
    TEST_NEAR("abs(-3) is 3" + in, vnl_math::abs(T(-3)), 3.0, 0.0);
    TEST_NEAR("sqr(-3) is 9" + in, vnl_math::sqr(T(-3)), 9.0, 0.0);
    TEST_NEAR("cube(-2) is -8" + in, vnl_math::cube(T(-2)), -8.0, 0.0);
    TEST("sgn of -2, 0, 2" + in, vnl_math::sgn(T(-2)) == -1 && vnl_math::sgn(T(0)) == 0 && vnl_math::sgn(T(2)) == 1,
         true);
    TEST("sgn0(0) is +1" + in, vnl_math::sgn0(T(0)), 1);
    TEST_NEAR("max(2, 3) is 3" + in, vnl_math::max(T(2), T(3)), 3.0, 0.0);
    TEST_NEAR("min(2, 3) is 2" + in, vnl_math::min(T(2), T(3)), 2.0, 0.0);
    TEST_NEAR("hypot(3, -4) is 5" + in, vnl_math::hypot(T(3), T(-4)), 5.0, ulps<T>(16));
    TEST_NEAR("hypot(0, 0) is 0" + in, vnl_math::hypot(T(0), T(0)), 0.0, 0.0);
    TEST("the old free-function spellings agree" + in,
         vnl_math_abs(T(-3)) == T(3) && vnl_math_sqr(T(3)) == T(9) && vnl_math_cube(T(2)) == T(8) &&
             vnl_math_sgn(T(-1)) == -1 && vnl_math_sgn0(T(0)) == 1 && vnl_math_max(T(1), T(2)) == T(2) &&
             vnl_math_min(T(1), T(2)) == T(1) && vnl_math_hypot(T(3), T(4)) == vnl_math::hypot(T(3), T(4)),
         true);
  }
};

void test_math() {
  TEST_NEAR("vnl_math::pi", vnl_math::pi, std::acos(-1.0), 1e-16);
  TEST_NEAR("vnl_math::pi_over_2", vnl_math::pi_over_2, std::acos(-1.0) / 2, 1e-16);
  TEST_NEAR("vnl_math::pi_over_4", vnl_math::pi_over_4, std::acos(-1.0) / 4, 1e-16);
  TEST_NEAR("vnl_math::e", vnl_math::e, std::exp(1.0), 1e-15);
  TEST_NEAR("vnl_math::sqrt2", vnl_math::sqrt2, std::sqrt(2.0), 1e-15);
  TEST_NEAR("vnl_math::deg_per_rad", vnl_math::deg_per_rad, 180 / std::acos(-1.0), 1e-13);
  TEST_NEAR("vnl_math::ln2", vnl_math::ln2, std::log(2.0), 1e-16);
  for_each_test_scalar<CheckMath>();
}

}  // namespace

TESTMAIN(test_math)
