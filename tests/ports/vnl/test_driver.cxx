// SPDX-License-Identifier: BSD-3-Clause
// The vnl driver (upstream: core/vnl/tests/test_driver.cxx).
#include "testlib/testlib_register.h"

DECLARE(test_vector);
DECLARE(test_matrix);
DECLARE(test_math);
DECLARE(test_rotation_matrix);
DECLARE(test_levenberg_marquardt);
DECLARE(test_quaternion);
DECLARE(test_real_polynomial);
DECLARE(test_sparse_matrix);
DECLARE(test_diag_matrix);
DECLARE(test_inverse);
DECLARE(test_numeric_traits);
DECLARE(test_random);
DECLARE(test_transpose);
DECLARE(test_vector_fixed_ref);
DECLARE(test_matrix_fixed_ref);

void register_tests() {
  REGISTER(test_vector);
  REGISTER(test_matrix);
  REGISTER(test_math);
  REGISTER(test_rotation_matrix);
  REGISTER(test_levenberg_marquardt);
  REGISTER(test_quaternion);
  REGISTER(test_real_polynomial);
  REGISTER(test_sparse_matrix);
  REGISTER(test_diag_matrix);
  REGISTER(test_inverse);
  REGISTER(test_numeric_traits);
  REGISTER(test_random);
  REGISTER(test_transpose);
  REGISTER(test_vector_fixed_ref);
  REGISTER(test_matrix_fixed_ref);
}

DEFINE_MAIN
