// SPDX-License-Identifier: BSD-3-Clause
/// Drift in clutter (issue #27): the thin-line test (thin_lines.h) used as a check rather than a
/// filter. The frame is solved as ever; then its matches without those on thin dark lines are
/// solved again from the same start. Where the two poses agree within what the frame's own
/// noise leaves the pose uncertain by, the lines did not pull the pose and the first solve
/// stands, bit for bit; where they part by more, the matches on the lines moved the pose: the
/// tracker takes the second pose or reports the frame uncertain (ThinLineParams::check). Only
/// frames where the test calls at least ThinLineParams::check_share of the matches lines are
/// checked.
#pragma once

#include <vector>

#include "edgetrack/edge_match.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/pose_solver.h"
#include "edgetrack/thin_line_params.h"
#include "visp3/core/vpImage.h"

namespace edgetrack {

/// Whether `lines` ask for the drift check: a check, and the test not already a filter.
inline bool drift_check_runs(const ThinLineParams& lines) { return !lines.enabled && lines.check != DriftAction::kNone; }

/// What the check found on a frame.
struct DriftVerdict {
  bool checked = false;  ///< the test called enough matches lines and the second pose was solved
  /// px, the largest distance between the two poses' projections of the model's overlay points
  /// (vertices, cylinder axis ends, circle centres)
  real parted_px{0};
  real allowed_px{0};    ///< px, ThinLineParams::check_sigmas times the second pose's uncertainty
  bool drifted = false;  ///< parted_px above allowed_px
};

/// The largest distance between the projections of the model's overlay points with `a` and with
/// `b`, over the points in front of the camera with both, pixels.
real largest_overlay_distance_px(const EdgeModel& model, const PinholeCamera& camera, const Se3& a, const Se3& b);

/// Marks each of `matches` an outlier whose used() hypothesis lies farther than the pose step's
/// Tukey cut, max(tukey_c * sigma, tukey_floor) px, along its normal from its point projected
/// with `pose`; returns how many are. A corrected frame's matches, the thin-line ones included,
/// are so counted at the pose it takes, for the status's shares and the contrast memory.
int mark_outliers_at(std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& pose, const real& sigma,
                     const PoseParams& pose_params);

/// The second solve's matches and pose, kept between frames so that a frame allocates nothing.
class DriftCheck {
 public:
  /// Room for `matches` matches: check then allocates nothing for up to that many.
  void reserve(size_t matches) { matches_.reserve(matches); }
  size_t heap_bytes() const { return matches_.capacity() * sizeof(EdgeMatch); }

  /// Solves `matches` less those on thin lines from `start` (pose_params, in `workspace`) and
  /// compares with `solved`; the second pose's uncertainty is taken with a residual scale of at
  /// least `sigma_floor`.
  DriftVerdict check(const vpImage<unsigned char>& grey, const std::vector<EdgeMatch>& matches, const Se3& solved,
                     const EdgeModel& model, const PinholeCamera& camera, const Se3& start,
                     const PoseParams& pose_params, const ThinLineParams& lines, const real& sigma_floor,
                     PoseWorkspace& workspace);

  /// The last check's second pose.
  const PoseSolution& solution() const { return solution_; }

 private:
  std::vector<EdgeMatch> matches_;
  PoseSolution solution_;
};

}  // namespace edgetrack
