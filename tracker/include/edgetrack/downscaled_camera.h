// SPDX-License-Identifier: BSD-3-Clause
/// The camera of a frame reduced by an integer factor: the one owner of this scaling, for
/// `--downscale` and for the detector's reduction of large frames (detection_reduction).
#pragma once

#include "edgetrack/pinhole_camera.h"

namespace edgetrack {

/// The camera of an image `factor` times smaller (pixel centres kept: u' = (u + 0.5) / f - 0.5);
/// `camera` itself for a factor of 1 or less.
PinholeCamera downscaled_camera(const PinholeCamera& camera, int factor);

}  // namespace edgetrack
