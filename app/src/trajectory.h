// SPDX-License-Identifier: BSD-3-Clause
/// Camera trajectories for synthetic sequences: the paper-like default and poses from a file.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack_app {

/// "paper": the paper's synthetic set-up (section 4): the object about 150 mm away with three
/// faces in view, turning and swaying smoothly, the image moving up to about 3 pixels per
/// frame at QVGA with px = 300. Any other value is a truth-format CSV file whose rows are used
/// in order (its first `frames` rows).
edgetrack::Result<std::vector<edgetrack::Se3>> make_trajectory(const std::string& kind, int frames);

/// The largest image displacement of any model vertex between consecutive poses, pixels.
double largest_vertex_motion(const edgetrack::EdgeModel& model, const edgetrack::PinholeCamera& camera,
                             const std::vector<edgetrack::Se3>& poses);

}  // namespace edgetrack_app
