// SPDX-License-Identifier: BSD-3-Clause
/// The constant templates test's driver: a separate executable because it links the templates
/// the tree's edgetrack generates at build time.
#include "testlib/testlib_register.h"

DECLARE(test_constant_templates);

void register_tests() { REGISTER(test_constant_templates); }

DEFINE_MAIN
