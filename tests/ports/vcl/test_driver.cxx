// SPDX-License-Identifier: BSD-3-Clause
#include "testlib/testlib_register.h"

DECLARE(test_vcl_shims);

void register_tests() { REGISTER(test_vcl_shims); }

DEFINE_MAIN
