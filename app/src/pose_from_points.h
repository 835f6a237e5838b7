// SPDX-License-Identifier: BSD-3-Clause
/// Initialisation from clicked points: the 3D points of a ViSP .init file and their 2D image
/// positions give camera_from_model, by a linear estimate (POSIT's scaled orthographic
/// iterations, DeMenthon and Davis) refined by Levenberg-Marquardt (our vnl port) on the
/// reprojection error.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack_app {

/// The bounds of the points files: at most 10000 points, coordinates within a kilometre, pixel
/// positions within a million pixels.
constexpr double kMaxInitPoints = 10000;
constexpr double kMaxPointCoordinate = 1000;
constexpr double kMaxPixelCoordinate = 1e6;

/// Reads a ViSP .init file: the number of points, then X Y Z per point (metres), # comments.
edgetrack::Result<std::vector<edgetrack::Vec3>> read_init_points(const std::string& path);
/// Reads image positions, one "u v" pair (pixels) per line, # comments.
edgetrack::Result<std::vector<edgetrack::Vec2>> read_image_points(const std::string& path);

struct PointPose {
  edgetrack::Se3 camera_from_model;
  double rms_px = 0;  ///< reprojection error after refinement
};

/// Needs at least 4 points, not all in one plane, in front of the camera. `source` names the
/// input in error messages.
edgetrack::Result<PointPose> pose_from_points(const std::vector<edgetrack::Vec3>& points_in_model,
                                              const std::vector<edgetrack::Vec2>& pixels,
                                              const edgetrack::PinholeCamera& camera, const std::string& source);

}  // namespace edgetrack_app
