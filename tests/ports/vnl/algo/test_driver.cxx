// SPDX-License-Identifier: BSD-3-Clause
// The vnl_algo driver (upstream: core/vnl/algo/tests/test_driver.cxx).
#include "testlib/testlib_register.h"

DECLARE(test_include);
DECLARE(test_svd);
DECLARE(test_qr);
DECLARE(test_cholesky);
DECLARE(test_symmetric_eigensystem);
DECLARE(test_determinant);

void register_tests() {
  REGISTER(test_include);
  REGISTER(test_svd);
  REGISTER(test_qr);
  REGISTER(test_cholesky);
  REGISTER(test_symmetric_eigensystem);
  REGISTER(test_determinant);
}

DEFINE_MAIN
