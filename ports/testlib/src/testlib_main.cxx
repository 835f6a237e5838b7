// SPDX-License-Identifier: BSD-3-Clause
// Mirrors VXL's core/testlib/testlib_main.cxx: the registry behind a test driver.
#include <cstdio>
#include <cstring>
#include <vector>

#include "testlib/testlib_register.h"

inline namespace edgetrack_ports {

namespace {
struct RegisteredTest {
  std::string name;
  TestMainFunction main_function;
};
std::vector<RegisteredTest>& registry() {
  static std::vector<RegisteredTest> tests;  // filled once by register_tests(), read-only after
  return tests;
}
}  // namespace

void testlib_register_test(const std::string& name, TestMainFunction main_function) {
  registry().push_back({name, main_function});
}

int testlib_main(int argc, char* argv[]) {
  // No name, or upstream's "all", runs every test and passes the remaining arguments to each.
  if (argc < 2 || std::strcmp(argv[1], "all") == 0) {
    if (argc >= 2) {
      --argc;
      ++argv;
    }
    int failures = 0;
    for (const auto& test : registry()) failures += test.main_function(argc, argv) != 0;
    return failures == 0 ? 0 : 1;
  }
  for (const auto& test : registry())
    if (test.name == argv[1]) return test.main_function(argc - 1, argv + 1);
  std::fprintf(stderr, "%s: no test named '%s'; registered tests are:\n", argv[0], argv[1]);
  for (const auto& test : registry()) std::fprintf(stderr, "  %s\n", test.name.c_str());
  return 2;
}

void testlib_cleanup() { registry().clear(); }

}  // inline namespace edgetrack_ports
