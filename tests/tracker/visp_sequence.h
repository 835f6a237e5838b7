// SPDX-License-Identifier: BSD-3-Clause
/// The real sequence of the tracking tests: ViSP's mbt/cube (640x480 PGM frames from
/// visp-images-data), tracked with the settings of its cube.xml from cube.0.pos, as
/// `edgetrack track` and examples/minimal do.
#pragma once

#include <functional>
#include <string>

#include "run_sequence.h"

namespace edgetrack_test {

/// Frames tracked, enough to cover the cube's first turn while staying quick under QEMU.
constexpr int kVispCubeFrames = 60;
/// The golden file of its double poses.
constexpr const char* kVispCubeGolden = "mbt_cube_double_poses.txt";

/// The first `frames` frames of mbt/cube under `visp_images` (the ViSP-images directory)
/// tracked; `loaded` is false (after a line on stderr) when a file cannot be read. `after_frame`,
/// when given, sees the tracker after each frame; `adjust`, when given, changes the settings
/// cube.xml gave; `model_file` is the model in mbt/ (cube.cao or cube_and_cylinder.cao).
SequenceRun run_visp_cube(const std::string& visp_images, int frames,
                          const std::function<void(const edgetrack::Tracker&)>& after_frame = {},
                          const std::function<void(edgetrack::TrackerParams&)>& adjust = {},
                          const std::string& model_file = "cube.cao");

}  // namespace edgetrack_test
