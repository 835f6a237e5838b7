// SPDX-License-Identifier: BSD-3-Clause
/// A control point paired with the image edge point found for it: the input of the pose step.
#pragma once

#include "edgetrack/control_points.h"

namespace edgetrack {

struct EdgeMatch {
  ControlPoint point;
  Vec2 found;            ///< the image edge point q_i, pixels
  bool outlier = false;  ///< set by the pose step when it gave the match no weight (ViSP's M_ESTIMATOR)
};

}  // namespace edgetrack
