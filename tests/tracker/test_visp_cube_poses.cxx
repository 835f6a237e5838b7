// SPDX-License-Identifier: BSD-3-Clause
/// The real sequence in the double builds: ViSP's mbt/cube tracked frame by frame gives the host
/// double run's poses within 1e-9 m and 1e-9 rad (golden/mbt_cube_double_poses.txt), on the
/// host and under QEMU on every ARM target alike.
#include "golden_check.h"
#include "testlib/testlib_test.h"
#include "visp_sequence.h"

using namespace edgetrack_test;

static void test_visp_cube_poses() {
  const SequenceRun run = run_visp_cube(EDGETRACK_VISP_IMAGES, kVispCubeFrames);
  TEST("mbt/cube's frames are read and every one is tracked", run.loaded, true);
  if (run.loaded) compare_poses_with_golden(kVispCubeGolden, run);
}

TESTMAIN(test_visp_cube_poses)
