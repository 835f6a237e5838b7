// SPDX-License-Identifier: BSD-3-Clause
/// Camera trajectories for synthetic sequences: the paper-like default and poses from a file.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/result.h"
#include "edgetrack/se3.h"
#include "edgetrack/synthetic_trajectory.h"

namespace edgetrack_app {

/// "paper": the paper's synthetic set-up (section 4), edgetrack::cube_trajectory: the object
/// about 150 mm away with three faces in view, turning and swaying smoothly, the image moving up
/// to about 3 pixels per frame at QVGA with px = 220. Any other value is a truth-format CSV file
/// whose rows are used in order (its first `frames` rows). largest_vertex_motion comes from
/// edgetrack/synthetic_trajectory.h too.
edgetrack::Result<std::vector<edgetrack::Se3>> make_trajectory(const std::string& kind, int frames);

}  // namespace edgetrack_app
