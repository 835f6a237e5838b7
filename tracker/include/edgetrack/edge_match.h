// SPDX-License-Identifier: BSD-3-Clause
/// A control point paired with the image edge point found for it: the input of the pose step.
#pragma once

#include "edgetrack/control_points.h"

namespace edgetrack {

/// The most edge hypotheses a control point keeps (moving_edges.h), `found` included.
constexpr int kMaxHypotheses = 4;

struct EdgeMatch {
  ControlPoint point;
  /// The image edge point q_i the pose step uses: on entry the strongest edge along the normal,
  /// on return the hypothesis its last robust round chose.
  Vec2 found;
  bool outlier = false;  ///< set by the pose step when it gave the match no weight (ViSP's M_ESTIMATOR)
  /// Other local maxima of the moving-edge likelihood along the normal, weaker ones later. The
  /// pose step swaps the one it chooses with `found`, so {found, alternatives} stays the same set.
  Vec2 alternatives[kMaxHypotheses - 1];
  int alternative_count = 0;
};

}  // namespace edgetrack
