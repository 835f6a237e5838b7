// SPDX-License-Identifier: BSD-3-Clause
#include "testlib/testlib_register.h"

DECLARE(test_camera_timing);
DECLARE(test_camera_response);

void register_tests() {
  REGISTER(test_camera_timing);
  REGISTER(test_camera_response);
}

DEFINE_MAIN
