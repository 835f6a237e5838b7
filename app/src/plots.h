// SPDX-License-Identifier: BSD-3-Clause
/// The paper's figures for a run, drawn with OpenCV (host build): Fig. 4, the tracking time of
/// each frame, and Fig. 5, the tracked camera position against ground truth on each axis.
#pragma once

#include <string>

#include "edgetrack/result.h"
#include "evaluation.h"

namespace edgetrack_app {

/// Writes DIR/fig4_time_per_frame.png and DIR/fig5_camera_position.png; DIR must exist.
edgetrack::Result<bool> write_plots(const std::string& dir, const Evaluation& evaluation);

}  // namespace edgetrack_app
