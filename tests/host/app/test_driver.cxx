// SPDX-License-Identifier: BSD-3-Clause
#include "testlib/testlib_register.h"

DECLARE(test_image_io);
DECLARE(test_pose_table);
DECLARE(test_frame_source);
DECLARE(test_pose_from_points);
DECLARE(test_guarded);

void register_tests() {
  REGISTER(test_image_io);
  REGISTER(test_pose_table);
  REGISTER(test_frame_source);
  REGISTER(test_pose_from_points);
  REGISTER(test_guarded);
}

DEFINE_MAIN
