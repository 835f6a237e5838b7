// SPDX-License-Identifier: BSD-3-Clause
/// Between frames: a damped constant-velocity prediction of the next pose, the moving-edge range
/// that follows the predicted image motion, and the wider search for a few frames after a loss.
#pragma once

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

struct MotionParams {
  /// The share of the measured motion per frame predicted into the next frame, once the motion
  /// exceeds twice the range (MotionModel::trust; 0: the paper's tracker, which starts every
  /// frame from the last pose; 1: constant velocity, which predicted best on the generated
  /// sequences, docs/ARCHITECTURE.md).
  real velocity_share = real(1);
  /// Per lost frame, the prediction moves on by this much less of the velocity: the longer
  /// nothing is measured, the less the last velocity says (0.8: a fifth less per frame, five
  /// lost frames move on by under four frames' motion in total).
  real lost_damping = real(0.8);
  /// The range grows by this share of the predicted image motion beyond the configured range:
  /// a constant-velocity prediction errs by the velocity's change over a frame, which on smooth
  /// hand-held motion stays under half the motion of a frame (docs/ARCHITECTURE.md).
  real range_per_motion = real(0.5);
  int max_range_factor = 4;  ///< the range never exceeds this many times the configured one
  int recovery_frames = 5;   ///< frames after a lost one searched with twice the range
  /// Frames after the start (or a reset) searched with twice the range: the velocity is known
  /// only once two frames have been tracked.
  int start_frames = 2;
  /// A frame lost from the prediction is tracked again from the last trusted pose, at rest,
  /// with the range grown by the image motion of one frame at the last velocity (retry_range):
  /// a hand that stops or reverses puts the object there, while the prediction has gone on by
  /// a frame's motion the other way. Frames tracked from the prediction cost nothing more.
  bool retry_from_trusted = true;
};

/// The largest image displacement of a model vertex between two poses (vertices behind the
/// camera in either pose are skipped), pixels.
real largest_image_shift(const EdgeModel& model, const PinholeCamera& camera, const Se3& a, const Se3& b);

/// The tracker's state between frames: the last trusted pose, the velocity measured from the
/// trusted poses (per frame, camera frame: next = exp(velocity) * last), and the frames since.
class MotionModel {
 public:
  MotionModel(const Se3& trusted, const MotionParams& params)
      : params_(params), trusted_(trusted), prediction_(trusted), wide_left_(params.start_frames) {}
  /// Later frames follow `params`; the motion so far is kept.
  void set_params(const MotionParams& params) { params_ = params; }

  /// The pose to start the next frame from: the last trusted pose moved on by the velocity
  /// once per frame since it (the velocity's share shrinks by `lost_damping` per lost frame).
  const Se3& prediction() const { return prediction_; }
  /// The last trusted pose (the start pose before any frame is trusted).
  const Se3& trusted() const { return trusted_; }
  /// True when the prediction is not the last trusted pose: the velocity moved it on, or
  /// frames were lost since.
  bool predicts_motion() const { return frames_since_trusted_ > 1 || next_share_ > real(0); }
  /// A trusted frame's pose: measures the velocity from the last trusted pose and predicts the
  /// next frame. The velocity is not applied while its image motion per frame is within the
  /// configured `range`, in full from twice the range on, and in proportion in between: the
  /// search alone finds a motion within its range, and a velocity measured from two poses
  /// carries their noise, which on a small range (QVGA, 2 px) cost more than the motion it
  /// predicted (docs/ARCHITECTURE.md).
  void trust(const Se3& camera_from_model, const EdgeModel& model, const PinholeCamera& camera, unsigned range);
  /// A lost frame: the prediction moves on by the velocity, damped once more per lost frame;
  /// the next recovery_frames frames search wider.
  void lose(const EdgeModel& model, const PinholeCamera& camera);
  /// The motion per frame measured from the last trusted poses (camera frame: a frame later the
  /// pose is exp(velocity()) times it); zero until two frames have been trusted.
  const Twist& velocity() const { return velocity_; }
  /// True when the last frame was lost (lose() after the last trust() or reset()).
  bool lost_last_frame() const { return frames_since_trusted_ > 1; }
  /// Starts again from `camera_from_model`, at rest, as a new model would.
  void reset(const Se3& camera_from_model);
  /// The moving-edge range for the next frame: `range` (twice it while recovering), grown by
  /// range_per_motion of the image motion of the velocity beyond it, at most
  /// max_range_factor * range.
  unsigned search_range(unsigned range) const;
  /// The range of a retry from the last trusted pose at rest: the range of search_range before
  /// the motion (twice `range` while recovering) plus the image motion of one frame at the last
  /// velocity, rounded up, at most max_range_factor * range. A reversal at the same speed
  /// puts the edges one frame's motion from the trusted pose.
  unsigned retry_range(unsigned range) const;

 private:
  /// `range` (twice it while recovering) grown by `beyond` pixels rounded up, at most
  /// max_range_factor * range.
  unsigned widened(unsigned range, const real& beyond) const;

  MotionParams params_;
  Se3 trusted_;
  Se3 prediction_;
  Twist velocity_{};
  real next_share_{0};  ///< the share of velocity_ the next lost frame moves the prediction by
  real motion_px_{0};   ///< the image motion of the prediction's next step (largest_image_shift)
  real speed_px_{0};    ///< the image motion of one frame at velocity_, undamped
  bool moving_ = false;  ///< a trusted frame has been seen since the start: velocity_ is measured from it
  int frames_since_trusted_ = 1;
  int wide_left_;       ///< frames still searched with twice the range
};

}  // namespace edgetrack
