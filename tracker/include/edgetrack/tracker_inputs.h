// SPDX-License-Identifier: BSD-3-Clause
/// The limits of what Tracker::create takes besides its settings (tracker_params.h): the
/// camera, the model and the start pose. Tracker::create and Tracker::reset apply them; a reader
/// or a program can apply them first to name the file an input came from.
#pragma once

#include <optional>
#include <string>

#include "edgetrack/edge_model.h"
#include "edgetrack/image_limits.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// Focal lengths lie in (0, kMaxFocalPx] pixels, the principal point within
/// +-kMaxPrincipalPointPx of the image's corner.
constexpr double kMaxFocalPx = 1e6;
constexpr double kMaxPrincipalPointPx = 1e6;
/// Lens coefficients (pinhole_camera.h) lie within +-kMaxLensCoefficient (real lenses stay
/// within a few units), as the calibration reader accepts them.
constexpr double kMaxLensCoefficient = 100;
/// Model coordinates lie within +-kMaxModelCoordinate metres, as the model readers accept them.
constexpr double kMaxModelCoordinate = 1e6;

/// Why the focal lengths or the principal point of `camera` are out of range, or nothing.
std::optional<Error> check_intrinsics(const PinholeCamera& camera);
/// Why `camera` cannot be tracked with (check_intrinsics, then the image size), or nothing. An image size of 0x0 is
/// taken from the first frame (Tracker::track).
std::optional<Error> check_camera(const PinholeCamera& camera);
/// Why `model` cannot be tracked (no primitive, too many for Edge-ID, a point not finite or
/// outside +-kMaxModelCoordinate), or nothing.
std::optional<Error> check_tracked_model(const EdgeModel& model);
/// What is wrong with a start pose, as the end of a sentence ("is not finite", "puts the model
/// behind the camera", ...), or nothing: each entry finite, the rotation orthonormal, the
/// translation within kMaxPosTranslation (pose_io.h) and in front of the camera (z > 0).
std::optional<std::string> check_start_pose(const Se3& camera_from_model);

}  // namespace edgetrack
