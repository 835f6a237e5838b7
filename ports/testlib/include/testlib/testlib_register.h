// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/testlib/testlib_register.h: one driver runs many named tests.
/// A library's test_driver.cxx DECLAREs each test, REGISTERs it in register_tests(),
/// and calls testlib_main(); `driver test_name` then runs that one test.
#pragma once

#ifdef TESTLIB_REGISTER_H_
#error "edgetrack's drop-in testlib/testlib_register.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <string>

inline namespace edgetrack_ports {

using TestMainFunction = int (*)(int, char*[]);

void testlib_register_test(const std::string& name, TestMainFunction main_function);
/// Runs the test named by argv[1] (every registered test when none is named or the name is
/// "all"); the test sees argv from its own name on.
int testlib_main(int argc, char* argv[]);
/// Forgets the registered tests (upstream's DEFINE_MAIN calls it before returning).
void testlib_cleanup();

/// Declares `name_main`, the entry point that a test file defines with TESTMAIN.
#define DECLARE(testname) int testname##_main(int argc, char* argv[])
#define REGISTER(testname) testlib_register_test(#testname, &testname##_main)
/// The driver's main(): the driver file defines register_tests() with its REGISTER lines.
#define DEFINE_MAIN                           \
  int main(int argc, char* argv[]) {          \
    register_tests();                         \
    const int status = testlib_main(argc, argv); \
    testlib_cleanup();                        \
    return status;                            \
  }

}  // inline namespace edgetrack_ports

/// Defined by the test driver (user code), so it stays in the global namespace.
void register_tests();
