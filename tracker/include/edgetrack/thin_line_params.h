// SPDX-License-Identifier: BSD-3-Clause
/// The thin-line test's settings (thin_lines.h): plain values, in TrackerParams, with no image
/// type, so that the public headers need none of the ports' but `real`.
#pragma once

#include <string>

#include "real/real.h"

namespace edgetrack {

/// What the drift check (drift_check.h) does with a frame whose pose the matches on thin lines
/// moved by more than its uncertainty allows.
enum class DriftAction {
  kNone = 0,    ///< no check: the tracker as without it
  kReport = 1,  ///< the frame is reported uncertain (StatusReason::kDrift), its pose kept
  kCorrect = 2  ///< the pose solved without the matches on thin lines is taken
};

/// The thin-line test's settings (TrackerParams::thin_lines), set by name from the XML's
/// <edgetrack><thin_lines> block and `track --thin-lines` (set_thin_line_param). As a filter
/// (`enabled`) it is off by default: on ViSP's real mbt/cube it also takes out true edges (a
/// third of the matches at return_share 0.2, docs/ME.md "Thin lines beside the edges"). As a
/// check (`check`) it is on by default, correcting: it changes a frame only where leaving those
/// matches out moves the pose by more than the frame's own noise allows, which taking out true
/// edges does not (docs/ME.md, "The thin-line test as a drift check").
struct ThinLineParams {
  /// As a filter: every match on a thin line takes its next hypothesis off the line, or goes.
  bool enabled = false;
  /// As a check (when `enabled` is off): the drift check's action.
  DriftAction check = DriftAction::kCorrect;
  /// The two poses part (largest overlay point distance) by more than this many times the
  /// second pose's uncertainty (pose_uncertainty.h, a standard deviation): drift. The second
  /// solve runs only where the matches off the lines would move the pose, to first order, by more
  /// than this many standard deviations (excluded_pull_sigmas), a bound on that parting.
  real check_sigmas{3};
  /// Pixels into the darker side (from the match) a line's darkest pixel may lie: its width.
  int dark_px = 2;
  /// Pixels beyond that darkest pixel where the image may come back.
  int beyond_px = 2;
  /// A match is on a line when the brightest pixel beyond is brighter than the darkest by at
  /// least this share of the edge's step (the pixel 2 px into the brighter side against the
  /// darkest): 0 < share <= 1. Measured on the generated clutter (docs/ME.md, "Thin lines").
  real return_share{0.2};
};

/// Sets the setting `name` (enabled, check, check_sigmas, dark_px, beyond_px, return_share) of `p` to `value`:
/// an empty string, or what is wrong (no such setting, a value outside its limits).
std::string set_thin_line_param(ThinLineParams& p, const std::string& name, double value);

}  // namespace edgetrack
