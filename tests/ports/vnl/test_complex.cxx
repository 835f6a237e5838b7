// SPDX-License-Identifier: BSD-3-Clause
// Complex vnl containers as upstream's test_complex.cxx: element-wise arithmetic of complex
// vectors, inner_product conjugating its second argument, and vnl_math on complex values.
#include <cmath>
#include <complex>

#include "testlib/testlib_test.h"
#include "vnl/vnl_complex.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

static void test_complex() {
  using C = std::complex<double>;
  const vnl_vector<C> a{C(1, 2), C(-3, 0.5)}, b{C(0, 1), C(2, -2)};
  TEST("sum", (a + b)[1], C(-1, -1.5));
  TEST("difference", (a - b)[0], C(1, 1));
  TEST("product by a scalar", (a * C(0, 1))[0], C(-2, 1));
  TEST_NEAR("quotient by a scalar", (a / C(0, 2))[0], C(1, -0.5), 1e-15);
  vnl_vector<C> c(a);
  c += b;
  TEST("+=", c[0], C(1, 3));
  c -= b;
  TEST("-=", c == a, true);
  c *= C(2, 0);
  TEST("*=", c[1], C(-6, 1));
  c /= C(2, 0);
  TEST_NEAR("/=", c[1], C(-3, 0.5), 1e-15);
  TEST_NEAR("inner_product() conjugates correctly", inner_product(a, b),
            a[0] * std::conj(b[0]) + a[1] * std::conj(b[1]), 1e-15);
  TEST_NEAR("inner_product(a, a) is |a|^2", inner_product(a, a), C(a.squared_magnitude(), 0), 1e-15);
  const vnl_matrix<C> m{{C(1, 1), C(0, 0)}, {C(0, 0), C(2, 0)}};
  TEST("complex matrix-vector product", (m * a)[0], C(-1, 3));
  TEST("vnl_math::isnan of a complex NaN", vnl_math::isnan(C(std::nan(""), 0)), true);
  TEST("vnl_math::isfinite", vnl_math::isfinite(C(1, 2)), true);
  TEST_NEAR("vnl_math::abs", vnl_math::abs(C(3, 4)), 5.0, 1e-15);
  TEST_NEAR("vnl_math::squared_magnitude", vnl_math::squared_magnitude(C(3, 4)), 25.0, 1e-15);
  TEST("vnl_math::sqr", vnl_math::sqr(C(0, 1)), C(-1, 0));
}

TESTMAIN(test_complex)
