// SPDX-License-Identifier: BSD-3-Clause
// The vcl driver: upstream's vcl tests that concern what vcl adds, and the paper's shims.
#include "testlib/testlib_register.h"

DECLARE(test_algorithm);
DECLARE(test_atomic_count);
DECLARE(test_cmath);
DECLARE(test_compiler);
DECLARE(test_complex);
DECLARE(test_include);
DECLARE(test_limits);
DECLARE(test_string);
DECLARE(test_vector);
DECLARE(test_vcl_shims);

void register_tests() {
  REGISTER(test_algorithm);
  REGISTER(test_atomic_count);
  REGISTER(test_cmath);
  REGISTER(test_compiler);
  REGISTER(test_complex);
  REGISTER(test_include);
  REGISTER(test_limits);
  REGISTER(test_string);
  REGISTER(test_vector);
  REGISTER(test_vcl_shims);
}

DEFINE_MAIN
