// SPDX-License-Identifier: BSD-3-Clause
/// Drift in clutter (issue #27): the thin-line test (thin_lines.h) used as a check rather than a
/// filter. The frame is solved as ever; then the matches whose hypothesis the solve used lies on
/// a thin dark line are masked out (EdgeMatch::excluded) and what the rest alone would do to the
/// pose is bounded to first order (excluded_pull_sigmas): where that move is within
/// ThinLineParams::check_sigmas of the pose's uncertainty, the lines did not pull the pose, no
/// second solve can find they did, and the first solve stands, bit for bit. Otherwise the rest
/// are solved again from the same start (LM set off at the bound's Gauss-Newton step); where the
/// two poses' overlays part by more than the check allows and the rest fit the second pose as
/// closely as all the matches fit the first (within the noise of a robust scale), by no more than
/// twice what the bound explains, the lines moved the pose: the tracker takes the second pose or
/// reports the frame uncertain (ThinLineParams::check).
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

/// The drift check's scratch memory, kept by its caller between frames (the tracker does): once
/// its buffers have reached the largest match count seen (or reserve's), the check allocates
/// nothing. What it holds between calls means nothing but the first solve's rows.
struct DriftWorkspace {
  /// A match's first-solve marks, held while the second solve overwrites them.
  struct HeldMarks {
    bool outlier = false;
    signed char chosen = 0;  ///< EdgeMatch::chosen, below kMaxHypotheses
  };
  std::vector<HeldMarks> held;
  /// The pose step's first solve's rows at the start, which the gate reads: the tracker points
  /// its PoseWorkspace::start_rows here before the frame's solve.
  StartRows start_rows;

  /// The heap its buffer holds (its capacity), for Tracker::memory.
  size_t heap_bytes() const;
  /// Room for `matches` matches.
  void reserve(size_t matches);
};

/// What the check found on a frame.
struct DriftVerdict {
  int lines = 0;  ///< matches whose used hypothesis the test called a line
  /// How far the other matches alone would move the pose, to first order, in standard
  /// deviations at gate_scale_px (excluded_pull_sigmas); 0 when no match was called a line.
  real pull_sigmas{0};
  /// px, the residual scale the other matches are predicted to fit at after that move, at least
  /// the floor: the scale of pull_sigmas.
  real gate_scale_px{0};
  bool checked = false;  ///< pull_sigmas above check_sigmas, and the second pose was solved
  /// px, the largest distance between the two poses' projections of the model's overlay points
  /// (vertices, cylinder axis ends, circle centres)
  real parted_px{0};
  real allowed_px{0};    ///< px, ThinLineParams::check_sigmas times the second pose's uncertainty
  /// The second pose's residual scale (over the matches not called lines) at most the first's
  /// (over all of them), within two standard errors of the second: the matches off the lines
  /// agree with one another as well without those on them, as they do where the lines pulled the
  /// pose, not where true edges were left out.
  bool fits_as_closely = false;
  /// parted_px above allowed_px, fits_as_closely, and parted_px within twice what the gate's
  /// first-order bound explains (pull_sigmas times the uncertainty at gate_scale_px): beyond, the rest
  /// settled in another basin from a start they do not hold.
  bool drifted = false;
  PoseSolution second;   ///< the second pose, when checked
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

/// The drift check of `solved`, the pose step's solution of `matches` from `start`: the matches
/// whose used() hypothesis lies on a thin line are masked out; where the rest would move the
/// pose by more than `lines.check_sigmas` standard deviations at the residual scale they are
/// predicted to fit at, at least `sigma_floor` (the second pose's own, which the check allows;
/// bounded from the rows `solved`'s first solve kept in `drift_workspace.start_rows`, without
/// them the bound is unconstrained), they are solved again from `start` (pose_params, in
/// `workspace`; LM set off at the bound's Gauss-Newton step of them, which has the same optimum)
/// and the two poses compared. `matches` come back as they came, the first solve's marks
/// included (held in `drift_workspace` meanwhile); nothing is allocated once the workspaces
/// have room.
DriftVerdict check_drift(const vpImage<unsigned char>& grey, std::vector<EdgeMatch>& matches, const PoseSolution& solved,
                         const EdgeModel& model, const PinholeCamera& camera, const Se3& start,
                         const PoseParams& pose_params, const ThinLineParams& lines, const real& sigma_floor,
                         PoseWorkspace& workspace, DriftWorkspace& drift_workspace);

}  // namespace edgetrack
