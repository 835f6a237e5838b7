// SPDX-License-Identifier: BSD-3-Clause
/// The tracking status rule.
#include "edgetrack/tracking_status.h"

#include <utility>

namespace edgetrack {

const char* status_name(TrackingStatus status) {
  switch (status) {
    case TrackingStatus::kTracked: return "tracked";
    case TrackingStatus::kUncertain: return "uncertain";
    case TrackingStatus::kLost: return "lost";
  }
  return "?";
}

const char* reason_name(StatusReason reason) {
  switch (reason) {
    case StatusReason::kNone: return "none";
    case StatusReason::kTooFewVisible: return "too few visible control points";
    case StatusReason::kPoseFailed: return "pose not solved";
    case StatusReason::kChanceResiduals: return "residuals at chance level";
    case StatusReason::kFewMatched: return "under half the visible points matched";
    case StatusReason::kManyOutliers: return "half or more of the matches outliers";
    case StatusReason::kFewToCheck: return "too few matches to check the fit";
    case StatusReason::kLooseFit: return "residual scale above a tracked frame's";
    case StatusReason::kNotReacquired: return "not found again after a loss";
    case StatusReason::kSaturated: return "fixed-point saturation";
    case StatusReason::kNotDetected: return "not found by the detector";
    case StatusReason::kUnconfirmed: return "detected, not yet confirmed by a tracked frame";
    case StatusReason::kPoseUnconstrained: return "the matches leave the pose unconstrained";
    case StatusReason::kPoseUndetermined: return "the matches leave the pose uncertain beyond the search range";
    case StatusReason::kUnsupported: return "the image gradient supports the pose's edges only at chance";
    case StatusReason::kOverLimit: return "more control points than the tracker's limit";
    case StatusReason::kDrift: return "the matches on thin lines beside the edges moved the pose";
  }
  return "?";
}

std::string check_status_params(const StatusParams& p) {
  const auto positive = [](const real& v) { return v > real(0); };
  if (!positive(p.tracked_scale_px)) return "status: the tracked residual scale must be positive (pixels)";
  if (!positive(p.lost_range_share) || !positive(p.lost_scale_floor_px) || p.lost_scale_floor_px < p.tracked_scale_px)
    return "status: the chance scale's share of the range must be positive, its floor at least the tracked scale";
  if (p.min_matched_share < real(0) || p.min_matched_share > real(1) || p.min_inlier_share < real(0) ||
      p.min_inlier_share > real(1))
    return "status: the matched and inlier shares must be in [0, 1]";
  if (!positive(p.max_pose_uncertainty_px) || !positive(p.lost_uncertainty_range_share))
    return "status: the pose uncertainty bounds must be positive";
  if (p.edge_location_px < real(0)) return "status: the edge location error must be at least 0 pixels";
  if (p.learn_frames < 0 || p.learn_frames > 1000) return "status: the learning frames must be 0 to 1000";
  if (!positive(p.learning_rate) || p.learning_rate > real(1)) return "status: the learning rate must be over 0 and at most 1";
  if (p.learned_deviations < real(0) || p.least_deviation_share < real(0))
    return "status: the learned deviations and the least deviation share must be at least 0";
  if (p.gradient_floor < real(1) || p.gradient_floor > real(1000))
    return "status: the gradient floor must be 1 to 1000 grey levels (a Sobel magnitude)";
  if (!positive(p.support_angle_deg) || p.support_angle_deg >= real(90))
    return "status: the support angle must be over 0 and under 90 degrees";
  if (p.confirm_support_share < real(0) || p.confirm_support_share > real(1))
    return "status: the confirming support share must be in [0, 1]";
  if (p.least_matched_share < real(0) || p.least_matched_share > p.min_matched_share || p.least_inlier_share < real(0) ||
      p.least_inlier_share > p.min_inlier_share)
    return "status: the least matched and inlier shares must be in [0, the fixed minimum shares]";
  return "";
}

std::string set_status_param(StatusParams& p, const std::string& name, double value) {
  if (name == "learn_frames") {
    if (!(value >= 0 && value <= 1000) || value != static_cast<double>(static_cast<int>(value)))
      return "learn_frames must be a whole number from 0 to 1000";
    p.learn_frames = static_cast<int>(value);
    return "";
  }
  const std::pair<const char*, real*> values[] = {{"tracked_scale_px", &p.tracked_scale_px},
                                                  {"lost_range_share", &p.lost_range_share},
                                                  {"lost_scale_floor_px", &p.lost_scale_floor_px},
                                                  {"min_matched_share", &p.min_matched_share},
                                                  {"min_inlier_share", &p.min_inlier_share},
                                                  {"max_pose_uncertainty_px", &p.max_pose_uncertainty_px},
                                                  {"lost_uncertainty_range_share", &p.lost_uncertainty_range_share},
                                                  {"edge_location_px", &p.edge_location_px},
                                                  {"learning_rate", &p.learning_rate},
                                                  {"learned_deviations", &p.learned_deviations},
                                                  {"least_deviation_share", &p.least_deviation_share},
                                                  {"least_matched_share", &p.least_matched_share},
                                                  {"least_inlier_share", &p.least_inlier_share},
                                                  {"gradient_floor", &p.gradient_floor},
                                                  {"support_angle_deg", &p.support_angle_deg},
                                                  {"confirm_support_share", &p.confirm_support_share}};
  for (const auto& named : values) {
    if (name != named.first) continue;
    if (!(value >= -1e6 && value <= 1e6)) return name + " must be a number within +-1e6";
    *named.second = real(value);  // set-up time conversion
    return "";
  }
  return "'" + name + "' is not a status setting";
}

StatusBounds fixed_bounds(const StatusParams& params) {
  return {params.tracked_scale_px, params.min_matched_share, params.min_inlier_share, params.max_pose_uncertainty_px,
          real(0)};
}

FrameStatus judge_frame(const FrameMeasures& m, const StatusParams& params, int min_points) {
  return judge_frame(m, params, min_points, fixed_bounds(params));
}

FrameStatus judge_frame(const FrameMeasures& m, const StatusParams& params, int min_points,
                        const StatusBounds& bounds) {
  const auto lost = [](StatusReason reason) { return FrameStatus{TrackingStatus::kLost, reason}; };
  const auto uncertain = [&m](StatusReason reason) {
    return m.after_loss ? FrameStatus{TrackingStatus::kLost, StatusReason::kNotReacquired}
                        : FrameStatus{TrackingStatus::kUncertain, reason};
  };
  if (m.visible < min_points) return lost(StatusReason::kTooFewVisible);
  if (!m.solved || m.kept < min_points) return lost(StatusReason::kPoseFailed);
  real lost_scale = params.lost_range_share * real(static_cast<int>(m.range));
  if (lost_scale < params.lost_scale_floor_px) lost_scale = params.lost_scale_floor_px;
  if (m.residual_scale > lost_scale) return lost(StatusReason::kChanceResiduals);
  if (m.pose_uncertainty_px > params.lost_uncertainty_range_share * real(static_cast<int>(m.range)))
    return lost(StatusReason::kPoseUndetermined);
  // Where the fit is loose (an approximate model) the projected edges are not expected on the
  // image's own, a pixel beside them: the support at the projected points tells nothing there.
  if (m.residual_scale <= params.tracked_scale_px && m.support_share < bounds.min_support_share)
    return lost(StatusReason::kUnsupported);
  if (m.kept < 2 * min_points) return uncertain(StatusReason::kFewToCheck);
  if (m.matched_share < bounds.min_matched_share) return uncertain(StatusReason::kFewMatched);
  if (m.inlier_share < bounds.min_inlier_share) return uncertain(StatusReason::kManyOutliers);
  if (m.residual_scale > bounds.tracked_scale_px) return uncertain(StatusReason::kLooseFit);
  if (m.saturations > 0) return uncertain(StatusReason::kSaturated);
  if (m.pose_uncertainty_px > bounds.max_pose_uncertainty_px) return uncertain(StatusReason::kPoseUnconstrained);
  return {TrackingStatus::kTracked, StatusReason::kNone};
}

}  // namespace edgetrack
