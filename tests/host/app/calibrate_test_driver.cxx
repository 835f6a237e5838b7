// SPDX-License-Identifier: BSD-3-Clause
#include "testlib/testlib_register.h"

DECLARE(test_calibrate);

void register_tests() { REGISTER(test_calibrate); }

DEFINE_MAIN
