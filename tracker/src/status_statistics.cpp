// SPDX-License-Identifier: BSD-3-Clause
/// The running statistics of the status measures and the bounds they give.
#include "edgetrack/status_statistics.h"

#include <algorithm>
#include <cmath>

namespace edgetrack {
namespace {

/// No bound of its own: the lost rules (chance residuals, pose undetermined) stand above it.
constexpr double kUnbounded = 100000;

/// The learned bound above which a measure departs (a residual scale, a pose uncertainty), at
/// least `fixed`.
real upper_bound(const RunningStatistic& s, const StatusParams& p, const real& fixed) {
  const real spread = std::max(s.deviation(), p.least_deviation_share * s.mean());
  return std::max(fixed, s.mean() + p.learned_deviations * spread);
}

/// The learned bound below which a share departs, between `least` and `fixed`; the least
/// deviation is a share of what the share misses (1 - mean), as the scale's is of the scale.
real lower_bound(const RunningStatistic& s, const StatusParams& p, const real& least, const real& fixed) {
  const real spread = std::max(s.deviation(), p.least_deviation_share * (real(1) - s.mean()));
  return std::min(fixed, std::max(least, s.mean() - p.learned_deviations * spread));
}

}  // namespace

void RunningStatistic::clear() { *this = RunningStatistic(); }

void RunningStatistic::add(real sample, real rate) {
  using std::fabs;
  if (++count_ == 1) {
    mean_ = sample;
    return;
  }
  const real weight = std::max(rate, real(1) / real(count_));
  const real difference = sample - mean_;
  mean_ += weight * difference;
  // The deviation from the mean before this sample: the sample's own pull does not hide it.
  deviation_ += weight * (fabs(difference) - deviation_);
}

void StatusStatistics::restart(bool trusted) {
  phase_ = trusted ? Phase::kLearning : Phase::kUnconfirmed;
  past_first_frame_ = false;
  scale_.clear();
  matched_.clear();
  inliers_.clear();
  uncertainty_.clear();
}

StatusBounds StatusStatistics::bounds(const StatusParams& p) const {
  // The detector's candidates (learn_frames 0) are judged on the way to their pose, where the
  // image cannot support them yet: the support rules are for the frames of a track.
  if (p.learn_frames == 0) return fixed_bounds(p);
  // Gradient orientations at chance fall within the support angle with probability angle / 90.
  const real chance_support = p.support_angle_deg / real(90);
  if (phase_ == Phase::kUnconfirmed) {
    // A detection nothing confirmed yet: the image must support its outline, not only its matches.
    StatusBounds unconfirmed = fixed_bounds(p);
    unconfirmed.min_support_share = std::max(chance_support, p.confirm_support_share);
    return unconfirmed;
  }
  if (phase_ == Phase::kLearning)
    return {real(kUnbounded), p.least_matched_share, p.least_inlier_share, real(kUnbounded), chance_support};
  return {upper_bound(scale_, p, p.tracked_scale_px), lower_bound(matched_, p, p.least_matched_share, p.min_matched_share),
          lower_bound(inliers_, p, p.least_inlier_share, p.min_inlier_share),
          upper_bound(uncertainty_, p, p.max_pose_uncertainty_px), chance_support};
}

void StatusStatistics::add(const FrameMeasures& m, TrackingStatus status, const StatusParams& p) {
  // A detected start is tracked first on the frame it was found on, and its pose was refined
  // on that very image: that frame confirms nothing.
  const bool found_on = phase_ == Phase::kUnconfirmed && !past_first_frame_;
  past_first_frame_ = true;
  if (p.learn_frames == 0 || status != TrackingStatus::kTracked || found_on) return;
  if (phase_ == Phase::kUnconfirmed) phase_ = Phase::kLearning;
  scale_.add(m.residual_scale, p.learning_rate);
  matched_.add(m.matched_share, p.learning_rate);
  inliers_.add(m.inlier_share, p.learning_rate);
  uncertainty_.add(m.pose_uncertainty_px, p.learning_rate);
  if (scale_.count() >= p.learn_frames) phase_ = Phase::kLearned;
}

}  // namespace edgetrack
