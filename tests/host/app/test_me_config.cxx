// SPDX-License-Identifier: BSD-3-Clause
// The <ecm> block of ViSP's mbt/cube.xml reads with its values; a block with a bad number is
// refused at its line, and a file without the block says so.
#include <fstream>

#include "me_config.h"
#include "testlib/testlib_test.h"

using namespace edgetrack_app;

static void test_me_config() {
  auto cube = read_ecm_config("/usr/share/visp-images-data/ViSP-images/mbt/cube.xml");
  TEST("mbt/cube.xml has an <ecm> block", cube.ok(), true);
  if (cube.ok()) {
    TEST_EQUAL("mask size", cube.value().mask_size, 5);
    TEST_EQUAL("number of masks", cube.value().mask_number, 180);
    TEST_EQUAL("tracking range", cube.value().range, 7);
    TEST_NEAR("edge threshold", cube.value().threshold, 5000, 0);
    TEST_NEAR("mu1", cube.value().mu1, 0.5, 0);
    TEST_NEAR("sample step", cube.value().sample_step, 4, 0);
  }
  const std::string bad = std::string(APP_TEST_TMP) + "/bad_ecm.xml";
  std::ofstream(bad) << "<conf>\n<ecm>\n<range>\n<tracking>seven</tracking>\n</range>\n</ecm>\n</conf>\n";
  auto refused = read_ecm_config(bad);
  TEST("a non-number is refused", refused.ok(), false);
  TEST_EQUAL("at its line", refused.error().line, 4);
  const std::string none = std::string(APP_TEST_TMP) + "/no_ecm.xml";
  std::ofstream(none) << "<conf><camera><px>300</px></camera></conf>\n";
  auto missing = read_ecm_config(none);
  TEST("a file without <ecm> is refused", missing.ok(), false);
  TEST("saying there is no <ecm> block", missing.error().message.find("no <ecm> block") != std::string::npos, true);
}

TESTMAIN(test_me_config)
