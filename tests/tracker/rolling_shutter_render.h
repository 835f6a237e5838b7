// SPDX-License-Identifier: BSD-3-Clause
/// A rolling shutter's frame for the tracking tests, as `edgetrack synth --readout` makes one:
/// row y of H is the scene at readout ((y + 0.5) / H - 0.5) frame intervals from the frame's
/// time, on the screw motion between the frame's pose and its neighbour's.
#pragma once

#include <vector>

#include "edgetrack/scene_renderer.h"

namespace edgetrack_test {

/// Renders frame `k` of `poses` (one per frame) read over `readout` frame intervals: `renders`
/// renders evenly spaced over the readout, each row taken from the one nearest its read time.
/// The motion before the first frame and after the last continues that of their neighbours.
void render_rolling_shutter(edgetrack::SceneRenderer& renderer, const edgetrack::EdgeModel& model,
                            const std::vector<edgetrack::Se3>& poses, int k, double readout, int renders,
                            uint32_t noise_seed, edgetrack::Rgb565Frame& frame);

}  // namespace edgetrack_test
