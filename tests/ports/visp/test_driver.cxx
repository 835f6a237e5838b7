// SPDX-License-Identifier: BSD-3-Clause
/// The testlib driver of ports/visp.
#include "testlib/testlib_register.h"

DECLARE(test_image_convert);
DECLARE(test_me_masks);
DECLARE(test_me_site);

void register_tests() {
  REGISTER(test_image_convert);
  REGISTER(test_me_masks);
  REGISTER(test_me_site);
}

DEFINE_MAIN
