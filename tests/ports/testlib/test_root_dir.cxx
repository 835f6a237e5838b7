// SPDX-License-Identifier: BSD-3-Clause
// testlib_root_dir() names the source tree: a file known to be there opens, and $VXLSRC,
// then $VCLSRC, then $VXL_SRC override the configured root, in upstream's order.
#include <cstdlib>
#include <fstream>
#include <string>

#include "testlib/testlib_root_dir.h"
#include "testlib/testlib_test.h"

static void test_root_dir() {
  const char* saved[3] = {std::getenv("VXLSRC"), std::getenv("VCLSRC"), std::getenv("VXL_SRC")};
  const std::string kept[3] = {saved[0] ? saved[0] : "", saved[1] ? saved[1] : "", saved[2] ? saved[2] : ""};
  unsetenv("VXLSRC");
  unsetenv("VCLSRC");
  unsetenv("VXL_SRC");

  const std::string path = testlib_root_dir() + "/ports/testlib/include/testlib/testlib_root_dir.h";
  std::ifstream in(path);
  TEST("the configured root holds ports/testlib/include/testlib/testlib_root_dir.h", !in, false);

  setenv("VXL_SRC", "/from/vxl_src", 1);
  TEST("$VXL_SRC overrides the configured root", testlib_root_dir(), std::string("/from/vxl_src"));
  setenv("VCLSRC", "/from/vclsrc", 1);
  TEST("$VCLSRC wins over $VXL_SRC", testlib_root_dir(), std::string("/from/vclsrc"));
  setenv("VXLSRC", "/from/vxlsrc", 1);
  TEST("$VXLSRC wins over both", testlib_root_dir(), std::string("/from/vxlsrc"));

  const char* names[3] = {"VXLSRC", "VCLSRC", "VXL_SRC"};
  for (int i = 0; i < 3; ++i) {
    if (saved[i]) {
      setenv(names[i], kept[i].c_str(), 1);
    } else {
      unsetenv(names[i]);
    }
  }
}

TESTMAIN(test_root_dir)
