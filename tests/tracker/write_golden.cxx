// SPDX-License-Identifier: BSD-3-Clause
/// Writes the golden files of the tracking tests: the camera position (metres, model frame) the
/// tracker finds in each frame of the synthetic sequences and of the sped-up cube and wood toy,
/// the cube and wood toy 30 % covered and played fast there and back, and with three edge hypotheses per control point. Run from a double build:
///   tracker_write_golden tests/tracker/golden
/// The other builds compare their own run with these files (test_tracking.cxx).
#include <cstdio>
#include <string>

#include "golden.h"
#include "run_sequence.h"

int main(int argc, char* argv[]) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <directory>\n", argv[0]);
    return 2;
  }
  using namespace edgetrack_test;
  for (int subsample : {1, kFastSpeedUp}) {
    for (Scene scene : {Scene::kCube, Scene::kWoodToy, Scene::kCubeCylinder}) {
      if (subsample > 1 && scene == Scene::kCubeCylinder) continue;  // no fast golden run of it
      SequenceSpec spec;
      spec.subsample = subsample;
      const SequenceRun run =
          run_sequence(scene, subsample > 1 ? kFastFrames : kGoldenFrames, false, edgetrack::TrackerParams{}, spec);
      const std::string path = std::string(argv[1]) + "/" + golden_name(scene, subsample);
      if (!run.loaded || !write_golden(path, run)) {
        std::fprintf(stderr, "%s: could not run the sequence or write the file\n", path.c_str());
        return 1;
      }
      std::printf("%s: %zu frames, mean position error %.3f mm\n", path.c_str(), run.frames.size(),
                  run.mean_position_error_mm);
    }
  }
  for (Scene scene : {Scene::kCube, Scene::kWoodToy}) {  // the covered and the reversal runs
    for (bool covered : {true, false}) {
      const SequenceSpec spec = covered ? covered_spec() : reversal_spec(scene);
      const int frames = covered ? kGoldenFrames : static_cast<int>(spec.poses.size());
      const SequenceRun run = run_sequence(scene, frames, false, edgetrack::TrackerParams{}, spec);
      const std::string path =
          std::string(argv[1]) + "/" + (covered ? covered_golden_name(scene) : reversal_golden_name(scene));
      if (!run.loaded || !write_golden(path, run)) {
        std::fprintf(stderr, "%s: could not run the sequence or write the file\n", path.c_str());
        return 1;
      }
      std::printf("%s: %zu frames, mean position error %.3f mm\n", path.c_str(), run.frames.size(),
                  run.mean_position_error_mm);
    }
  }
  for (Scene scene : {Scene::kCube, Scene::kWoodToy}) {  // the multiple-hypothesis runs
    edgetrack::TrackerParams multiple;
    multiple.hypotheses = kMultipleHypotheses;
    const SequenceRun run = run_sequence(scene, kGoldenFrames, false, multiple);
    const std::string path = std::string(argv[1]) + "/" + golden_name(scene, 1, kMultipleHypotheses);
    if (!run.loaded || !write_golden(path, run)) {
      std::fprintf(stderr, "%s: could not run the sequence or write the file\n", path.c_str());
      return 1;
    }
    std::printf("%s: %zu frames, mean position error %.3f mm\n", path.c_str(), run.frames.size(),
                run.mean_position_error_mm);
  }
  return 0;
}
