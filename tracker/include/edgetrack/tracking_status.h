// SPDX-License-Identifier: BSD-3-Clause
/// The tracking status of a frame: tracked, uncertain or lost, the reason, and the measures the
/// rule reads (docs/ARCHITECTURE.md, "Tracking status").
#pragma once

#include <cstdint>
#include <string>

#include "real/real.h"

namespace edgetrack {

enum class TrackingStatus { kTracked = 0, kUncertain = 1, kLost = 2 };

/// Why a frame is not tracked (kNone when it is); the first rule that applies names it.
enum class StatusReason {
  kNone = 0,
  kTooFewVisible,     ///< lost: fewer visible control points than the pose step needs (object gone)
  kPoseFailed,        ///< lost: too few matches for the pose step, or its solve failed
  kChanceResiduals,   ///< lost: the residuals are spread as matches at chance over the range
  kFewMatched,        ///< uncertain: under half the visible control points matched and kept
  kManyOutliers,      ///< uncertain: the robust solve gave half or more of the matches no weight
  kFewToCheck,        ///< uncertain: too few matches kept to tell a fit from chance
  kLooseFit,          ///< uncertain: the robust residual scale is above a tracked frame's
  kNotReacquired,     ///< lost: after a lost frame, only a frame that would be tracked counts as found again
  kSaturated,         ///< uncertain: fixed-point results saturated during the frame
  kNotDetected,       ///< lost: the detector ran and did not find the model (AutoInitTracker)
  kUnconfirmed,       ///< uncertain: the detector found the model on this frame; a tracked frame confirms it
  kPoseUnconstrained,  ///< uncertain: the matches leave the overlay's position uncertain by more than the bound
  kPoseUndetermined,   ///< lost: the matches leave it uncertain by more than the search reaches
  kUnsupported,        ///< lost: the image gradient supports the pose's edges no more than at chance
  kOverLimit,          ///< lost: the frame would sample more control points than the tracker's TrackerLimits
  kDrift               ///< uncertain: the matches on thin lines beside the edges moved the pose (drift_check.h)
};
constexpr int kStatusReasonCount = static_cast<int>(StatusReason::kDrift) + 1;

const char* status_name(TrackingStatus status);
const char* reason_name(StatusReason reason);

/// What the status rule reads, all from one frame.
struct FrameMeasures {
  int visible = 0;          ///< visible control points
  int matched = 0;          ///< of those, the ones the moving edges found
  int kept = 0;             ///< of those, the ones the robust pose solve kept (nonzero weight)
  bool solved = false;      ///< the pose step solved (PoseSolution::solved)
  real matched_share{0};    ///< kept / visible
  real inlier_share{0};     ///< kept / matched
  real residual_scale{0};   ///< px, 1.4826 * median |distance| of the matches at the final pose
  /// px, largest move of a control point along its normal, prediction to solved pose; no rule
  /// of its own: a point moved beyond its search cannot be an inlier, which the shares count
  real correction_px{0};
  real translation_change_mm{0};  ///< solved pose against the prediction
  real rotation_change_deg{0};
  unsigned range = 0;       ///< the moving-edge range this frame searched, px
  bool after_loss = false;  ///< the previous frame was lost
  std::uint64_t saturations = 0;  ///< fixed-point saturations counted during the frame (0 in float builds)
  /// px, the overlay's standard deviation the matches leave (pose_uncertainty.h), with the
  /// residual scale taken as at least StatusParams::edge_location_px
  real pose_uncertainty_px{0};
  /// Of the visible control points, the share whose projection with the solved pose has image
  /// gradient within StatusParams::support_angle_deg of the edge's normal (edge_support.h): how
  /// much of the model's visible outline the image supports, not only at the matches.
  real support_share{0};
  /// The frame's quality figure: the mean angle, degrees, between the image gradient and the
  /// projected edge's normal over the visible control points, projected with the solved pose,
  /// that have a gradient over StatusParams::gradient_floor (0 to 90: a few degrees on a held
  /// object, about 45 for orientations at chance; 0 when no point has one).
  real gradient_angle_deg{0};
};

/// The rule's thresholds, each with what it stands for.
struct StatusParams {
  /// Robust scale of a tracked frame: edge localisation and model error keep it within a pixel.
  real tracked_scale_px = real(1);
  /// Lost when the scale exceeds lost_range_share * range and lost_scale_floor_px: matches at
  /// chance over +-range have |distance| spread evenly over [0, range], so with a share p of
  /// them on the model's edges the median is range (1/2 - p) / (1 - p); at p = 1/4 that is
  /// range / 3, a scale of 0.49 range. The floor keeps tracked frames (up to ~1 px) apart from
  /// it when the range is small.
  real lost_range_share = real(0.6);
  real lost_scale_floor_px = real(1.5);
  real min_matched_share = real(0.5);  ///< below: uncertain
  real min_inlier_share = real(0.5);   ///< below: uncertain (the median scale breaks down at half)
  /// Above: uncertain. One standard deviation of a model vertex's image position that the
  /// residual noise leaves in the pose: past a pixel the overlay visibly wanders where no edge holds it.
  real max_pose_uncertainty_px = real(1);
  /// Lost when the pose uncertainty exceeds this share of the range searched: the overlay may
  /// be off by more than the next frame's search reaches, so the tracker cannot be expected to
  /// find the edges again from it (a few edges left of an object leaving the view).
  real lost_uncertainty_range_share = real(1);
  /// The least residual scale the pose uncertainty assumes, px: how well the moving edges
  /// place an edge against the true one (blur, the raster, the masks' orientation steps; what
  /// `tracking_eval_me_offsets` measures at the true pose). That error is shared along an edge,
  /// so the residuals about the fitted pose do not show it; with a few edges left the pose fits
  /// them exactly and the residual scale falls far below it (docs/ARCHITECTURE.md).
  real edge_location_px = real(0.3);

  // What a tracked frame looks like is learned from the scene (status_statistics.h): a user's
  // model approximates the object, so its residual scale and pose uncertainty on a well held
  // frame may be several times a perfect model's. The fixed bounds above are the least the
  // learned ones may be; the lost rules (chance residuals, pose undetermined) stay as they are.
  /// Frames after a trusted start (a given pose, or a detection once a frame tracked by the
  /// fixed bounds confirms it) that teach the statistics before a frame is judged by its
  /// departure from them; they are judged by the lost rules and the share floors below only.
  /// 0: no learning, the fixed bounds throughout (the detector's refinement of a candidate).
  int learn_frames = 5;
  /// The weight of a new frame in the running statistics once 1 / learning_rate frames have
  /// been seen (an EWMA's lambda; before, each frame weighs 1/n): how fast they follow the scene.
  real learning_rate = real(0.1);
  /// A tracked frame's measure lies within this many deviations of the learned mean (toward
  /// worse: a larger residual scale or pose uncertainty, a smaller share).
  real learned_deviations = real(3);
  /// The deviation taken as at least this share of the mean (of a share: of what it misses,
  /// 1 - mean): a few calm frames underestimate the spread of the frames to come.
  real least_deviation_share = real(0.2);
  /// The learned matched and inlier shares' bounds stay at or above these floors (and at or
  /// below min_matched_share and min_inlier_share): a pose resting on under a quarter of the
  /// visible model, or with three quarters of its matches outliers, is never called tracked.
  real least_matched_share = real(0.25);
  real least_inlier_share = real(0.25);

  // Whether the image supports the pose along the whole of its edges (edge_support.h): a wrong
  // pose can explain its own matches (a detection on clutter, a walk onto parallel lines) but
  // not the gradient along the rest of its outline.
  /// The least Sobel gradient magnitude (grey levels) of an image edge: the Sobel response to a
  /// step of h grey levels is 4 h, so 40 is a 10-level step, about six standard deviations of
  /// the response to pixel noise of 2 levels.
  real gradient_floor = real(40);
  /// The largest angle, degrees, between the gradient and the projected normal of an edge the
  /// gradient supports. Orientations at chance (clutter, texture) fall within it with
  /// probability support_angle_deg / 90, the support share's chance level: a pose fitting its
  /// matches within tracked_scale_px is lost when its share is under that (its outline lies on
  /// texture or flat image). A looser fit (an approximate model's, several pixels) puts the
  /// projected edges beside the image's, where the support at them says nothing.
  real support_angle_deg = real(30);
  /// The least support share of a detection until a frame tracked from it confirms it: a
  /// wrong candidate explains the matches it was refined on, which the detector found on the
  /// object's own edges, but it lies beside the object along part of its outline, over flat
  /// image or clutter. A true pose has gradient along all of its outline but the edges between
  /// faces of one shade and what covers it; three quarters leaves a quarter for those.
  real confirm_support_share = real(0.67);
};

/// The bounds between a tracked and an uncertain frame (the lost rules have their own): the
/// fixed ones of StatusParams, or those learned from the scene (status_statistics.h).
struct StatusBounds {
  real tracked_scale_px{1};          ///< above: uncertain (loose fit)
  real min_matched_share{0.5};       ///< below: uncertain
  real min_inlier_share{0.5};        ///< below: uncertain
  real max_pose_uncertainty_px{1};   ///< above: uncertain (pose unconstrained)
  /// Below: lost (the image does not support the pose's outline). Not a fixed bound: a track's
  /// frames after a trusted start have the chance level, a detection not yet confirmed
  /// confirm_support_share (status_statistics.h).
  real min_support_share{0};
};

/// The fixed bounds of `params`.
StatusBounds fixed_bounds(const StatusParams& params);

/// The first setting outside its limits, as "status: ...", or an empty string.
std::string check_status_params(const StatusParams& params);

/// Sets the setting whose field is named `name` (tracked_scale_px, learn_frames, ...) to
/// `value`, for the configuration file's <status> block and the command line; the problem
/// (no such setting, a fraction for learn_frames) or an empty string. Limits: check_status_params.
std::string set_status_param(StatusParams& params, const std::string& name, double value);

struct FrameStatus {
  TrackingStatus status = TrackingStatus::kLost;
  StatusReason reason = StatusReason::kPoseFailed;
};

/// The status rule: lost when there is nothing to track, the pose could not be solved, the
/// residuals look like chance, or the matches leave the model's image position uncertain by
/// more than the search reaches; uncertain when the pose rests on a minority of the model, fits
/// loosely, fixed point saturated, or that uncertainty is over max_pose_uncertainty_px; tracked
/// otherwise.
/// After a lost frame an uncertain one stays lost: the prediction it started from is weak, and
/// a wider search on clutter finds fits that are loose but not at chance. Fewer kept matches
/// than twice `min_points` (12 for six pose parameters) leave too few residual degrees of
/// freedom for the fit to say anything: uncertain.
/// `min_points` is the pose step's minimum (PoseParams::min_points).
/// `bounds` separate tracked from uncertain frames (by default the fixed ones of `params`).
FrameStatus judge_frame(const FrameMeasures& measures, const StatusParams& params, int min_points);
FrameStatus judge_frame(const FrameMeasures& measures, const StatusParams& params, int min_points,
                        const StatusBounds& bounds);

}  // namespace edgetrack
