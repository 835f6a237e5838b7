// SPDX-License-Identifier: BSD-3-Clause
/// Tracking frames N times smaller than the camera's (`--downscale N` of track and compare): the
/// camera (edgetrack::downscaled_camera) and the pixel-sized settings follow the frame.
#pragma once

#include "edgetrack/downscaled_camera.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/tracker.h"
#include "image_io.h"

namespace edgetrack_app {

/// The sample step, the range and the level-of-detail length are pixels of the input frames,
/// like the camera: scaled with it (the area by factor^2), the smaller frames get the same
/// control points on the object and a search that reaches no farther into the scene (the range
/// rounded down, at least 1 pixel).
void downscale_settings(edgetrack::TrackerParams& params, int factor);

/// The frame the tracker reads: the read pixels themselves at factor 1, else the frame
/// `factor` times smaller in `small`, which the view points into: grey8 for a grey8 frame, else
/// RGB24.
edgetrack::FrameView tracked_frame(const FramePixels& pixels, int factor, FramePixels& small);

}  // namespace edgetrack_app
