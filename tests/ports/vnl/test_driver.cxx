// SPDX-License-Identifier: BSD-3-Clause
#include "testlib/testlib_register.h"

DECLARE(test_vector);
DECLARE(test_matrix);
DECLARE(test_math);
DECLARE(test_rotation_matrix);
DECLARE(test_levenberg_marquardt);

void register_tests() {
  REGISTER(test_vector);
  REGISTER(test_matrix);
  REGISTER(test_math);
  REGISTER(test_rotation_matrix);
  REGISTER(test_levenberg_marquardt);
}

DEFINE_MAIN
