// SPDX-License-Identifier: BSD-3-Clause
// The <ecm> block of ViSP's mbt/cube.xml reads with its values; a block with a bad number is
// refused at its line, and a file without the block says so. Applied, its values become the
// tracker's moving-edge settings and sample step; values the tracker cannot use are refused.
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
    edgetrack::TrackerParams params;
    auto applied = apply_ecm_config(cube.value(), "cube.xml", params);
    TEST("cube.xml applies", applied.ok(), true);
    TEST_NEAR("threshold applied", static_cast<double>(params.me.getThreshold()), 5000, 0);
    TEST_EQUAL("mask size applied", params.me.getMaskSize(), 5u);
    TEST_EQUAL("mask number applied", params.me.getMaskNumber(), 180u);
    TEST_EQUAL("range applied", params.me.getRange(), 7u);
    TEST_NEAR("sample step applied to the control points", static_cast<double>(params.sampling.step), 4, 0);
  }
  EcmConfig partial;
  partial.mask_size = 3;
  partial.mask_number = 90;
  edgetrack::TrackerParams params;
  const edgetrack::TrackerParams defaults;
  TEST("a partial block applies", apply_ecm_config(partial, "p.xml", params).ok(), true);
  TEST_EQUAL("its mask size", params.me.getMaskSize(), 3u);
  TEST_EQUAL("its mask number", params.me.getMaskNumber(), 90u);
  TEST_EQUAL("the masks are rebuilt: 2 degrees apart", params.me.getAngleStep(), 2u);
  TEST_EQUAL("range left at its default", params.me.getRange(), defaults.me.getRange());
  TEST_NEAR("threshold left at its default", static_cast<double>(params.me.getThreshold()),
            static_cast<double>(defaults.me.getThreshold()), 0);
  TEST_NEAR("step left at its default", static_cast<double>(params.sampling.step),
            static_cast<double>(defaults.sampling.step), 0);
  for (auto bad : {EcmConfig{1, -1, -1, -1, -1, -1, -1}, EcmConfig{-1, 0, -1, -1, -1, -1, -1},
                   EcmConfig{-1, 181, -1, -1, -1, -1, -1}, EcmConfig{-1, -1, 0, -1, -1, -1, -1},
                   EcmConfig{-1, -1, -1, 0, -1, -1, -1}, EcmConfig{-1, -1, -1, -1, -1, -1, 0}}) {
    auto refused = apply_ecm_config(bad, "bad.xml", params);
    TEST("an unusable value is refused", refused.ok(), false);
    TEST("naming the file", refused.error().file, std::string("bad.xml"));
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
