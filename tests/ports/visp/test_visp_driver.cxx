// SPDX-License-Identifier: BSD-3-Clause
/// The testlib driver of ports/visp.
#include "testlib/testlib_register.h"

DECLARE(test_vpImageConvert);
DECLARE(test_vpMe);
DECLARE(test_vpMeSite);

void register_tests() {
  REGISTER(test_vpImageConvert);
  REGISTER(test_vpMe);
  REGISTER(test_vpMeSite);
}

DEFINE_MAIN
