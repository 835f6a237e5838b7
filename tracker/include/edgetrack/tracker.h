// SPDX-License-Identifier: BSD-3-Clause
/// The frame loop of the paper's tracker: visible edges (Edge-ID), grey scaling, moving edges,
/// pose. Each step is a free function with plain inputs and outputs; Tracker holds the state
/// between frames and times each step.
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/contrast_memory.h"
#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/face_visibility.h"
#include "edgetrack/frame_view.h"
#include "edgetrack/grey_conversion.h"
#include "edgetrack/motion_model.h"
#include "edgetrack/moving_edges.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/pose_solver.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"
#include "edgetrack/status_statistics.h"
#include "edgetrack/tracking_status.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"

namespace edgetrack {

/// How the grey step turns the frame into the grey image the moving edges read (a grey8 frame,
/// or the Y plane of NV21 and I420, packed, is read in place in both modes).
enum class GreyScaling {
  kOnDemand,   ///< only the boxes the control points' searches read (me_search_box.h)
  kWholeFrame  ///< every pixel, as the paper does
};

/// The tracker's settings, each in one place; check_tracker_params (tracker_params.h) holds their
/// limits, and the configuration reader (visp_config.h) fills them from a ViSP XML file.
struct TrackerParams {
  /// The moving edges with upstream's meanings, and the one home of every <ecm> setting: range,
  /// threshold, mask size and number, mu1/mu2 and the sample step that spaces the control
  /// points. The range is the configured one: each frame searches it or wider
  /// (MotionModel::search_range). mu1/mu2 bound the contrast a site accepts against the one
  /// its model point showed in the last trusted frame (contrast_memory.h).
  vpMe me;
  FaceVisibilityParams faces;  ///< <face> and <lod>: face angles, clipping, level of detail
  int border = 10;             ///< control points nearer the image border than this (pixels) are dropped
  PoseParams pose;
  /// Edge hypotheses each control point keeps (1 to kMaxHypotheses): the strongest edge along
  /// its normal and the next local maxima of the likelihood; the pose step uses the one nearest
  /// to the projection (moving_edges.h, pose_solver.h). 1 is the paper's single match, and the
  /// default: 3 lower the error where a parallel distractor edge lies inside the range but
  /// beyond the edge's own mask response, and raise it slightly on the plain generated
  /// sequences (docs/ME.md).
  int hypotheses = 1;
  GreyScaling grey = GreyScaling::kOnDemand;
  MotionParams motion;  ///< prediction between frames and the range that follows it
  StatusParams status;  ///< the tracked / uncertain / lost rule
};

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
  /// Checks the inputs and returns a tracker starting from `initial` (camera_from_model).
  static Result<Tracker> create(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial,
                                const TrackerParams& params);

  /// Tracks one frame of the camera's size, in any layout (frame_view.h); an Error, and nothing
  /// changes, when check_frame refuses it.
  Result<FrameResult> track(const FrameView& frame);

  /// Visible edges come from `source` from the next frame on (nullptr: the portable
  /// renderer). The source must outlive the tracker or be reset first.
  void set_edge_id_source(EdgeIdSource* source) { edge_id_source_ = source; }
  /// `observer` sees each step begin and end from the next frame on (nullptr: none). It must
  /// outlive the tracker or be reset first.
  void set_step_observer(StepObserver* observer) { step_observer_ = observer; }

  /// The pose the next frame starts from (the prediction after the last frame).
  const Se3& camera_from_model() const { return camera_from_model_; }
  /// Continues from `camera_from_model`, at rest, at the next frame (a new initialisation; lost
  /// frames need none: the tracker predicts and searches wider by itself); keeps the buffers,
  /// the parameters and the Edge-ID source, and starts the faces' visibility afresh (all
  /// hidden, as a new tracker's). False, and nothing changes, when the pose puts the model
  /// behind the camera.
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
  const std::vector<ControlPoint>& control_points() const { return visible_; }
  const std::vector<EdgeMatch>& matches() const { return matches_; }
  const EdgeIdBuffer& edge_ids() const { return edge_ids_; }
  /// The faces' visibility and the edges tracked in the last frame.
  const FaceVisibility& face_visibility() const { return face_visibility_; }

 private:
  Tracker(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial, const TrackerParams& params);
  /// The grey step: converts what the moving edges will read and returns the image they read.
  const vpImage<unsigned char>& grey_scale(const FrameView& frame, unsigned int& converted);
  void begin(Step step) {
    if (step_observer_) step_observer_->begin(step);
  }
  void end(Step step) {
    if (step_observer_) step_observer_->end(step);
  }
  /// The four steps from `start` with the moving edges searching `range`, guessing when `start`
  /// is a guess (no contrasts, no weights at the start), then the status of what they found.
  void attempt(const FrameView& frame, const Se3& start, unsigned range, bool guessing, FrameResult& result);
  /// The status measures of the attempt from `start` and the rule's judgement.
  void judge(const Se3& start, std::uint64_t saturations, FrameResult& result) const;
  /// The motion model and the contrast memory take the frame's result; the next frame's start.
  void conclude(FrameResult& result);

  EdgeModel model_;
  PinholeCamera camera_;
  TrackerParams params_;
  vpMe me_;                  ///< params_.me with this frame's search range
  SamplingParams sampling_;  ///< from params_: the sample step of params_.me, the border, the clipping
  FaceVisibility face_visibility_;
  FaceVisibility faces_before_;  ///< face_visibility_ before this frame, for a retry
  Se3 camera_from_model_;
  MotionModel motion_;
  EdgeIdBuffer edge_ids_;
  EdgeIdSource* edge_id_source_ = nullptr;
  StepObserver* step_observer_ = nullptr;
  /// The grey frame; on demand, only the current frame's search boxes are up to date.
  vpImage<unsigned char> grey_;
  BoxGreyScaler grey_boxes_;
  /// Borrows the frame's own grey bytes (grey_in_place) during track only.
  vpImage<unsigned char> grey_in_place_;
  // Each frame's points, matches and pose buffers, kept so that a frame allocates nothing once
  // they have grown to the largest frame seen.
  std::vector<ControlPoint> sampled_;
  std::vector<ControlPoint> visible_;
  std::vector<EdgeMatch> matches_;
  PoseWorkspace pose_workspace_;
  ContrastMemory contrast_memory_;  ///< the last trusted frame's edge contrasts
  std::vector<real> references_;    ///< per visible point, its remembered contrast or 0
  std::vector<unsigned char> borrowed_;  ///< per visible point, nonzero: its reference is its primitive's
  bool started_ = false;            ///< a frame has been trusted since the start or the last reset
  bool start_is_guess_ = false;     ///< the last reset's StartPose was kGuess
  StatusStatistics status_statistics_;  ///< what a tracked frame looks like on this scene
};

}  // namespace edgetrack
