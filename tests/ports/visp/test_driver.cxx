// SPDX-License-Identifier: BSD-3-Clause
/// The testlib driver of ports/visp.
#include "testlib/testlib_register.h"

DECLARE(test_image_convert);
DECLARE(test_image_point);
DECLARE(test_math);
DECLARE(test_matrix);
#ifndef EDGETRACK_NO_ME_LINE_ELLIPSE
DECLARE(test_me_ellipse);
DECLARE(test_me_line);
#endif
DECLARE(test_me_masks);
DECLARE(test_me_response);
DECLARE(test_me_site);
DECLARE(test_robust);
DECLARE(test_transformations);
DECLARE(test_upstream_api);

void register_tests() {
  REGISTER(test_image_convert);
  REGISTER(test_image_point);
  REGISTER(test_math);
  REGISTER(test_matrix);
#ifndef EDGETRACK_NO_ME_LINE_ELLIPSE
  REGISTER(test_me_ellipse);
  REGISTER(test_me_line);
#endif
  REGISTER(test_me_masks);
  REGISTER(test_me_response);
  REGISTER(test_me_site);
  REGISTER(test_robust);
  REGISTER(test_transformations);
  REGISTER(test_upstream_api);
}

DEFINE_MAIN
