// SPDX-License-Identifier: BSD-3-Clause
/// Writes the golden files of the tracking tests: the camera position (metres, model frame) the
/// tracker finds in each frame of the synthetic sequences and of the sped-up cube and wood toy,
/// the cube and wood toy 30 % covered and played fast there and back, and with three edge
/// hypotheses per control point, each with its full poses beside it; and the full poses of
/// ViSP's mbt/cube. Run from the host double build:
///   tracker_write_golden tests/tracker/golden
/// The other builds compare their own run with these files (golden_check.h).
#include <cstdio>
#include <string>

#include "golden.h"
#include "run_sequence.h"
#include "visp_sequence.h"

namespace {

using namespace edgetrack_test;

/// Writes the run's positions file `name` (when not empty) and its poses file; false after a
/// line on stderr when the run failed or a file cannot be written.
bool save(const std::string& dir, const std::string& positions_name, const std::string& poses_name,
          const SequenceRun& run) {
  const bool written = run.loaded && (positions_name.empty() || write_golden(dir + "/" + positions_name, run)) &&
                       write_golden_poses(dir + "/" + poses_name, run);
  if (!written) {
    std::fprintf(stderr, "%s/%s: could not run the sequence or write the file\n", dir.c_str(), poses_name.c_str());
    return false;
  }
  std::printf("%s/%s: %zu frames", dir.c_str(), poses_name.c_str(), run.frames.size());
  if (!run.truth.empty()) std::printf(", mean position error %.3f mm", run.mean_position_error_mm);
  std::printf("\n");
  return true;
}

bool save(const std::string& dir, const std::string& positions_name, const SequenceRun& run) {
  return save(dir, positions_name, poses_golden_name(positions_name), run);
}

}  // namespace

int main(int argc, char* argv[]) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <directory>\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  for (int subsample : {1, kFastSpeedUp}) {
    for (Scene scene : {Scene::kCube, Scene::kWoodToy, Scene::kCubeCylinder}) {
      if (subsample > 1 && scene == Scene::kCubeCylinder) continue;  // no fast golden run of it
      SequenceSpec spec;
      spec.subsample = subsample;
      const SequenceRun run =
          run_sequence(scene, subsample > 1 ? kFastFrames : kGoldenFrames, false, edgetrack::TrackerParams{}, spec);
      if (!save(dir, golden_name(scene, subsample), run)) return 1;
    }
  }
  for (Scene scene : {Scene::kCube, Scene::kWoodToy}) {  // the covered and the reversal runs
    for (bool covered : {true, false}) {
      const SequenceSpec spec = covered ? covered_spec() : reversal_spec(scene);
      const int frames = covered ? kGoldenFrames : static_cast<int>(spec.poses.size());
      const SequenceRun run = run_sequence(scene, frames, false, edgetrack::TrackerParams{}, spec);
      if (!save(dir, covered ? covered_golden_name(scene) : reversal_golden_name(scene), run)) return 1;
    }
  }
  for (Scene scene : {Scene::kCube, Scene::kWoodToy}) {  // the multiple-hypothesis runs
    edgetrack::TrackerParams multiple;
    multiple.hypotheses = kMultipleHypotheses;
    if (!save(dir, golden_name(scene, 1, kMultipleHypotheses), run_sequence(scene, kGoldenFrames, false, multiple)))
      return 1;
  }
  return save(dir, "", kVispCubeGolden, run_visp_cube(EDGETRACK_VISP_IMAGES, kVispCubeFrames)) ? 0 : 1;
}
