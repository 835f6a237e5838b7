// SPDX-License-Identifier: BSD-3-Clause
/// What a tracked frame looks like on this scene: running statistics of the status measures
/// from the frames after a trusted start, and the bounds of the status rule they give
/// (docs/ARCHITECTURE.md, "Tracking status"). O(1) per frame, no allocation.
#pragma once

#include "edgetrack/tracking_status.h"
#include "real/real.h"

namespace edgetrack {

/// An exponentially weighted mean and mean absolute deviation (the statistics of an EWMA
/// chart): the first samples weigh 1/n each, so that the mean starts as the plain average,
/// then `rate` each, so that the scene's slow changes are followed. No square root: the
/// absolute deviation stands for the spread (for a normal distribution 0.8 standard deviation).
class RunningStatistic {
 public:
  void clear();
  void add(real sample, real rate);
  real mean() const { return mean_; }
  real deviation() const { return deviation_; }
  int count() const { return count_; }

 private:
  real mean_{0};
  real deviation_{0};
  int count_ = 0;
};

/// The learned bounds of the status rule and the learning's phase. The bounds only widen the
/// fixed ones (a scene the model fits better than a perfect model's generated frames keeps
/// them), up to the lost rules for the residual scale and the pose uncertainty and to the
/// share floors of StatusParams.
class StatusStatistics {
 public:
  /// How far the statistics trust the frames: not at all (a guessed or a detected start, until
  /// a frame tracked by the fixed thresholds confirms it), learning (the first
  /// StatusParams::learn_frames frames after a trusted start, judged by the outer bounds), or
  /// learned (judged by their departure from the statistics).
  enum class Phase { kUnconfirmed, kLearning, kLearned };

  /// Starts learning afresh: `trusted` after a given pose, unconfirmed otherwise.
  void restart(bool trusted);
  /// The bounds this frame is judged by (StatusParams holds the fixed ones and the outer ones).
  StatusBounds bounds(const StatusParams& params) const;
  /// Takes a frame's measures and its status: tracked frames teach the statistics; an
  /// unconfirmed start is confirmed by the first tracked frame after the one it was found on
  /// (the first frame after restart).
  void add(const FrameMeasures& measures, TrackingStatus status, const StatusParams& params);

  Phase phase() const { return phase_; }
  const RunningStatistic& residual_scale() const { return scale_; }
  const RunningStatistic& matched_share() const { return matched_; }
  const RunningStatistic& inlier_share() const { return inliers_; }
  const RunningStatistic& pose_uncertainty() const { return uncertainty_; }

 private:
  Phase phase_ = Phase::kLearning;
  bool past_first_frame_ = false;  ///< a frame was added since the last restart
  RunningStatistic scale_;
  RunningStatistic matched_;
  RunningStatistic inliers_;
  RunningStatistic uncertainty_;
};

}  // namespace edgetrack
