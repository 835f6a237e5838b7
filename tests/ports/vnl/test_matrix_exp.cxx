// SPDX-License-Identifier: BSD-3-Clause
// vnl_matrix_exp as upstream's test_matrix_exp.cxx: exp of a rotation generator is the
// rotation (cos, sin), exp(0) = I, and the fixed-size form agrees.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/vnl_double_3x3.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_exp.h"

static void test_matrix_exp() {
  const double theta = 0.7;
  vnl_matrix<double> x(2, 2, 0.0);
  x(0, 1) = -theta, x(1, 0) = theta;
  const vnl_matrix<double> e = vnl_matrix_exp(x);
  TEST_NEAR("exp of a rotation generator: cos", e(0, 0), std::cos(theta), 1e-10);
  TEST_NEAR("exp of a rotation generator: sin", e(1, 0), std::sin(theta), 1e-10);
  TEST_NEAR("exp of a rotation generator: -sin", e(0, 1), -std::sin(theta), 1e-10);
  TEST("exp(0) = I", vnl_matrix_exp(vnl_matrix<double>(3, 3, 0.0)).is_identity(), true);
  vnl_double_3x3 n(0.0);
  n(0, 1) = 1, n(1, 2) = 1;  // nilpotent: exp = I + N + N^2 / 2
  vnl_double_3x3 en;
  TEST("the fixed-size form returns true", vnl_matrix_exp(n, en, 1e-14), true);
  TEST_NEAR("exp of a nilpotent matrix: (0,2) = 1/2", en(0, 2), 0.5, 1e-14);
  TEST_NEAR("exp of a nilpotent matrix: (0,1) = 1", en(0, 1), 1.0, 1e-14);
}

TESTMAIN(test_matrix_exp)
