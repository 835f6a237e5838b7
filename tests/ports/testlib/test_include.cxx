// SPDX-License-Identifier: BSD-3-Clause
// Every public testlib header compiles on its own and together (upstream's test_include.cxx).
#include "testlib/testlib_register.h"
#include "testlib/testlib_root_dir.h"
#include "testlib/testlib_test.h"

int main() { return 0; }
