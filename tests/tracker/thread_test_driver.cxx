// SPDX-License-Identifier: BSD-3-Clause
/// The thread test's driver: a separate host-only executable, linked with the thread library.
#include "testlib/testlib_register.h"

DECLARE(test_two_threads);

void register_tests() { REGISTER(test_two_threads); }

DEFINE_MAIN
