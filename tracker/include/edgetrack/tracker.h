// SPDX-License-Identifier: BSD-3-Clause
/// The frame loop of the paper's tracker: visible edges (Edge-ID), grey scaling, moving edges,
/// pose. Each step is a free function with plain inputs and outputs; Tracker holds the state
/// between frames and times each step.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/edge_match.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/face_visibility.h"
#include "edgetrack/frame_view.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/pose_solver.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"
#include "edgetrack/tracker_limits.h"
#include "edgetrack/tracker_memory.h"
#include "edgetrack/tracker_params.h"
#include "edgetrack/tracking_status.h"

namespace edgetrack {

/// Draws the Edge-ID image the visibility test reads. The tracker's default is the portable
/// EdgeIdBuffer::render; the host app plugs in GL this way (`--visibility gl`).
class EdgeIdSource {
 public:
  virtual ~EdgeIdSource() = default;
  /// Fills `out` (EdgeIdBuffer::assign or render) for the model seen from camera_from_model.
  virtual void draw(const EdgeModel& model, const Se3& camera_from_model, EdgeIdBuffer& out) = 0;
};

/// The paper's four steps (Table 1).
enum class Step { kVisibleEdges = 0, kGreyScaling = 1, kMovingEdges = 2, kPose = 3 };
constexpr int kStepCount = 4;
const char* step_name(Step step);

/// Called at the start and the end of each step of Tracker::track (a benchmark opens and
/// closes its instruction-count windows there); a retried frame (FrameResult::retried) runs the
/// four steps twice.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual void begin(Step step) = 0;
  virtual void end(Step step) = 0;
};

/// What one frame did: its pose and status, the step times (host clock, nanoseconds) and the
/// counts.
struct FrameResult {
  /// The solved pose; on a lost frame, the prediction the frame started from (the last trusted
  /// pose moved on by the damped velocity), which is also where the next frame starts.
  Se3 camera_from_model;
  TrackingStatus status = TrackingStatus::kLost;
  StatusReason reason = StatusReason::kPoseFailed;
  FrameMeasures measures;  ///< what the status rule read
  int64_t step_ns[kStepCount] = {0, 0, 0, 0};
  int points_sampled = 0;  ///< visible control points
  int points_matched = 0;  ///< of those, the ones the moving edges found and the pose kept
  unsigned int grey_pixels = 0;  ///< pixels the grey step converted
  PoseSolution pose;       ///< residuals and LM counts
  /// Lost from the prediction, the frame was tracked again from the last trusted pose
  /// (MotionParams::retry_from_trusted); the result is the retry's unless it too was lost. The
  /// step times, the converted pixels and the step observer's windows cover both attempts.
  bool retried = false;
};

class Tracker {
 public:
  /// Checks the inputs (tracker_inputs.h, check_tracker_params) and returns a tracker starting
  /// from `initial` (camera_from_model), or an Error naming the input refused.
  static Result<Tracker> create(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial,
                                const TrackerParams& params);
  /// The same with stated maxima (tracker_limits.h): every buffer is allocated here, for the
  /// largest frame `limits` allow, and track allocates nothing (set_params rebuilds the moving
  /// edges' masks, which allocates). An Error when the limits are incomplete, or the model or
  /// the camera exceed them.
  static Result<Tracker> create(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial,
                                const TrackerParams& params, const TrackerLimits& limits);
  /// A copy tracks on from where the original is, independently of it (with the same limits,
  /// its buffers allocated by the copy).
  Tracker(const Tracker& other);
  Tracker& operator=(const Tracker& other);
  Tracker(Tracker&& other) noexcept;
  Tracker& operator=(Tracker&& other) noexcept;
  ~Tracker();

  /// Tracks one frame of the camera's size, in any layout (frame_view.h); an Error, and nothing
  /// changes, when check_frame refuses it. A camera created with a 0x0 image takes the size of
  /// the first frame it is given (checked as create checks a camera).
  Result<FrameResult> track(const FrameView& frame);

  /// Tracks the next frames with `params`, checked as create checks them (an Error, and nothing
  /// changes, when check_tracker_params refuses them). The pose, the motion so far and the
  /// remembered contrasts carry on.
  std::optional<Error> set_params(const TrackerParams& params);
  const TrackerParams& params() const;

  /// Visible edges come from `source` from the next frame on (nullptr: the portable
  /// renderer). The source must outlive the tracker or be reset first.
  void set_edge_id_source(EdgeIdSource* source);
  /// `observer` sees each step begin and end from the next frame on (nullptr: none). It must
  /// outlive the tracker or be reset first.
  void set_step_observer(StepObserver* observer);

  /// The pose the next frame starts from (the prediction after the last frame).
  const Se3& camera_from_model() const;
  /// Continues from `camera_from_model`, at rest, at the next frame (a new initialisation; lost
  /// frames need none: the tracker predicts and searches wider by itself); keeps the buffers,
  /// the parameters and the Edge-ID source, and starts the faces' visibility afresh (all
  /// hidden, as a new tracker's). False, and nothing changes, when check_start_pose refuses
  /// the pose (not finite, the model behind the camera or farther than kMaxPosTranslation).
  /// A given pose (a .pos file, a click, a refined detection) is where the edges are: the first
  /// frame takes their contrast there and weighs the matches by their distance to it. A guess
  /// (a detector's unrefined candidate) is not trusted for the contrasts, as the prediction
  /// after a lost frame is not, until a frame is tracked from it; its distances still weigh the
  /// first solve (PoseParams::weigh_at_start), which the prediction after a loss does not.
  /// A refined detection (kDetected) is a given pose for the contrasts, but the status keeps
  /// the fixed bounds until a frame tracked by them confirms it, and learns the scene from
  /// there (status_statistics.h); a given pose starts the learning at once.
  enum class StartPose { kGiven, kGuess, kDetected };
  bool reset(const Se3& camera_from_model, StartPose start = StartPose::kGiven);
  /// The visible control points and the matches of the last frame (with the pose step's
  /// outliers marked), for tests and display.
  const std::vector<ControlPoint>& control_points() const;
  const std::vector<EdgeMatch>& matches() const;
  const EdgeIdBuffer& edge_ids() const;
  /// The faces' visibility and the edges tracked in the last frame.
  const FaceVisibility& face_visibility() const;
  const TrackerLimits& limits() const;
  /// The heap it holds now, per buffer (tracker_memory.h).
  TrackerMemory memory() const;

 private:
  /// The state between frames and each frame's buffers, with the moving edges' masks and grey
  /// images (tracker.cpp): none of the ports' types shows here.
  class State;
  explicit Tracker(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace edgetrack
