// SPDX-License-Identifier: BSD-3-Clause
#include "testlib/testlib_register.h"

DECLARE(test_minpack_mgh);

void register_tests() { REGISTER(test_minpack_mgh); }

DEFINE_MAIN
