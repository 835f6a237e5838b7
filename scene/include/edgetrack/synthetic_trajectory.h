// SPDX-License-Identifier: BSD-3-Clause
/// Smooth camera trajectories of the generated sequences (the paper's section 4 set-up) and the
/// image motion they cause; shared by the tracking tests, the benchmarks and `edgetrack synth`.
#pragma once

#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// camera_from_model per frame for the paper's cube: the 60 mm cube about 150 mm away with three
/// faces in view, turning and swaying along slow sines; with the QVGA camera px = py = 220 its
/// image moves by up to about 3 pixels per frame.
std::vector<Se3> cube_trajectory(int frames);

/// camera_from_model per frame for the wood toy: about 150 mm away, seen from above and one
/// side, turning so that its tower sweeps over its base (self-occlusion).
std::vector<Se3> wood_toy_trajectory(int frames);

/// The largest image displacement of any model vertex between consecutive poses, pixels.
double largest_vertex_motion(const EdgeModel& model, const PinholeCamera& camera, const std::vector<Se3>& poses);

}  // namespace edgetrack
