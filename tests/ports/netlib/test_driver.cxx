// SPDX-License-Identifier: BSD-3-Clause
#include "testlib/testlib_register.h"

DECLARE(test_minpack_mgh);
DECLARE(test_pose_lm);

void register_tests() {
  REGISTER(test_minpack_mgh);
  REGISTER(test_pose_lm);
}

DEFINE_MAIN
