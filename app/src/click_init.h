// SPDX-License-Identifier: BSD-3-Clause
/// `track --init-click I.init` (host, with a display): the user clicks the .init file's 3D points
/// on the first frame, one by one, in a window; our pose-from-points (POSIT + LM) turns the
/// clicks into the initial pose, which is shown projected for confirmation, and can be saved so
/// that the run can be repeated without a display.
#pragma once

#include <string>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"
#include "image_io.h"

namespace edgetrack_app {

struct ClickInitOptions {
  std::string init_path;    ///< ViSP .init file: the 3D points to click, in order
  std::string save_points;  ///< when set, the clicks are written here (the --init-points format)
  std::string save_pose;    ///< when set, the accepted pose is written here (a .pos for --init-pose)
};

/// The pose from points clicked on `frame` (the camera's size). An Error when there is no
/// display (DISPLAY unset or unreachable) or no GUI in this build, when the user cancels
/// (Esc or closing the window), or when the .init file or a save file fails.
edgetrack::Result<edgetrack::Se3> click_initial_pose(const ClickInitOptions& options, const RgbImage& frame,
                                                     const edgetrack::PinholeCamera& camera,
                                                     const edgetrack::EdgeModel& model);

}  // namespace edgetrack_app
