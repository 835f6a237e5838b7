// SPDX-License-Identifier: BSD-3-Clause
/// The test driver of compare's child supervision (built when compare is).
#include "testlib/testlib_register.h"

DECLARE(test_visp_child_supervised);

void register_tests() { REGISTER(test_visp_child_supervised); }

DEFINE_MAIN
