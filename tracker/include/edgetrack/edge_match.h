// SPDX-License-Identifier: BSD-3-Clause
/// A control point paired with the image edge point found for it: the input of the pose step.
#pragma once

#include "edgetrack/control_points.h"

namespace edgetrack {

/// The most edge hypotheses a control point keeps (moving_edges.h), `found` included.
constexpr int kMaxHypotheses = 4;

/// search_moving_edges writes each field over a reused match's, all but the alternatives past
/// alternative_count (never read): a new field must be set there too.
struct EdgeMatch {
  ControlPoint point;
  /// Where `point` sits in the control points it was searched from (search_moving_edges), so
  /// that the tracker pairs the match back with its visible point without comparing points
  /// (-1: none). Read by RowTimes::again, which checks it against the points it kept, and by
  /// the tracker on its own matches only.
  int point_index = -1;
  Vec2 found;            ///< the image edge point q_i: the strongest edge along the normal, pixels
  bool outlier = false;  ///< set by the pose step when it gave the match no weight (ViSP's M_ESTIMATOR)
  /// Left out of the pose step: solve_pose gives it no weight and counts it in no median. The
  /// drift check's mask over the tracker's own matches (drift_check.h); off everywhere else. It
  /// sits in the padding after `outlier`: the match is no larger.
  bool excluded = false;
  /// The mask response at `found` with the mask oriented along the normal (positive: the image
  /// darkens along the normal, as thin_lines.cpp reads it): the edge's contrast and polarity, for
  /// the next frame's contrast test.
  real contrast{0};
  /// Other local maxima of the moving-edge likelihood along the normal, weaker ones later.
  Vec2 alternatives[kMaxHypotheses - 1];
  int alternative_count = 0;
  /// The hypothesis the pose step's last robust round used: 0 is `found`, a + 1 alternatives[a].
  int chosen = 0;

  /// alternative_count within what the array holds: a caller's match may say anything, and
  /// nothing reads past alternatives[].
  int alternatives_held() const {
    return alternative_count < 0 ? 0 : alternative_count < kMaxHypotheses - 1 ? alternative_count : kMaxHypotheses - 1;
  }
  /// The chosen hypothesis; `found` when chosen names none held.
  const Vec2& used() const { return chosen > 0 && chosen <= alternatives_held() ? alternatives[chosen - 1] : found; }
};

}  // namespace edgetrack
