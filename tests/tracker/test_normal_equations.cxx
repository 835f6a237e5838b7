// SPDX-License-Identifier: BSD-3-Clause
/// The pose step's normal-equations solver (PoseSolver::kNormalEquations) tracks the golden
/// sequences to lmder's poses: the double golden files were written with lmder, and each
/// frame's camera position must stay within the same tolerances of them as lmder's own run in
/// this build (golden_check.cxx: 0.01 mm in every frame and 0.001 mm on average in double,
/// 0.1 mm and 0.01 mm in S40.23).
#include <cstdio>

#include "golden.h"
#include "golden_check.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

static void test_normal_equations_keep_lmder_poses() {
  TrackerParams params;
  params.pose.solver = PoseSolver::kNormalEquations;
  for (Scene scene : {Scene::kCube, Scene::kWoodToy}) {
    for (int subsample : {1, kFastSpeedUp}) {
      SequenceSpec spec;
      spec.subsample = subsample;
      const SequenceRun run = run_sequence(scene, subsample > 1 ? kFastFrames : kGoldenFrames, false, params, spec);
      TEST("the sequence runs with the normal-equations solver", run.loaded, true);
      if (!run.loaded) continue;
      int unsolved = 0;
      for (const FrameResult& f : run.frames) unsolved += !f.pose.solved;
      TEST("every frame's pose is solved", unsolved, 0);
      std::printf("%s x%d: ", scene == Scene::kCube ? "cube" : "wood toy", subsample);
      compare_with_golden(golden_name(scene, subsample), run, false);  // another solver: positions only
    }
  }
}

TESTMAIN(test_normal_equations_keep_lmder_poses)
