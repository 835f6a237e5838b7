// SPDX-License-Identifier: BSD-3-Clause
/// The test driver of the app's GL tests (OSMesa in the process: kept apart from app_test_all).
#include "testlib/testlib_register.h"

DECLARE(test_track_visibility_gl);

void register_tests() { REGISTER(test_track_visibility_gl); }

DEFINE_MAIN
