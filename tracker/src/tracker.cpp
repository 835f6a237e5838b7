// SPDX-License-Identifier: BSD-3-Clause
/// The tracker's frame loop, one line per step, timed per step like the paper's Table 1.
#include "edgetrack/tracker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "edgetrack/angles.h"
#include "edgetrack/contrast_memory.h"
#include "edgetrack/drift_check.h"
#include "edgetrack/edge_support.h"
#include "edgetrack/grey_conversion.h"
#include "edgetrack/me_search_box.h"
#include "edgetrack/millimetres.h"
#include "edgetrack/motion_model.h"
#include "edgetrack/moving_edges.h"
#include "edgetrack/pose_uncertainty.h"
#include "edgetrack/rolling_shutter.h"
#include "edgetrack/status_statistics.h"
#include "edgetrack/thin_lines.h"
#include "edgetrack/tracker_inputs.h"
#include "real/sum_of_products.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"

namespace edgetrack {
namespace {

/// One lap per step on the host's monotonic clock, added to the frame's time for the step.
class StepClock {
 public:
  StepClock() : last_(std::chrono::steady_clock::now()) {}
  void lap(Step step, FrameResult& result) {
    const auto now = std::chrono::steady_clock::now();
    result.step_ns[static_cast<int>(step)] += std::chrono::duration_cast<std::chrono::nanoseconds>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_;
};

/// The largest move of a control point along its normal from where the frame sampled it to
/// where `pose` projects it, pixels: what the moving-edge search had to reach. The shift
/// n . (project(P) - pixel) is |a X + b Y + c Z| / Z; the largest is found by comparing cross
/// products, so that one division is left for the frame (an ARMv5TE has no divider). Through a
/// lens the shift needs the projection itself. `projected`, given through a lens and else when
/// shared (shares_projections), holds each point at `pose` (project_points).
real largest_normal_shift(const std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& pose,
                          const ProjectedPoints* projected) {
  using std::fabs;
  if (camera.distorted()) {
    real worst(0);
    for (size_t p = 0; p < points.size(); ++p)
      if (projected->in_front[p])
        worst = std::max(worst, fabs(dot(points[p].normal, projected->pixel[p] - points[p].pixel)));
    return worst;
  }
  real worst_numerator(0), worst_depth(1);
  for (size_t k = 0; k < points.size(); ++k) {
    const ControlPoint& p = points[k];
    const Vec3 in_camera = projected ? projected->in_camera[k] : pose * p.point_in_model;
    if (in_camera.z <= real(0)) continue;
    const real offset = dot(p.normal, Vec2{camera.u0, camera.v0} - p.pixel);
    const real numerator = fabs(sum_of_products(p.normal.x * camera.px, in_camera.x, p.normal.y * camera.py,
                                                in_camera.y, offset, in_camera.z));
    if (numerator * worst_depth > worst_numerator * in_camera.z) {
      worst_numerator = numerator;
      worst_depth = in_camera.z;
    }
  }
  return worst_numerator / worst_depth;
}

/// The step times and the converted pixels of `from` carried into `to`, measured after it.
void carry_costs(const FrameResult& from, FrameResult& to) {
  std::copy(from.step_ns, from.step_ns + kStepCount, to.step_ns);
  to.grey_pixels = from.grey_pixels;
}

}  // namespace

/// Everything a Tracker holds; the frame loop runs on it unchanged, one pointer away.
class Tracker::State {
 public:
  State(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial, const TrackerParams& params,
        const TrackerLimits& limits);
  /// With stated limits, every buffer's room for the largest frame they allow (a copy of a
  /// vector keeps only its size: a copied tracker reserves again).
  void reserve_for_limits();

  Result<FrameResult> track(const FrameView& frame);
  bool reset(const Se3& camera_from_model, StartPose start);
  void set_params(const TrackerParams& params);

  EdgeModel model_;
  PinholeCamera camera_;
  TrackerParams params_;
  TrackerLimits limits_;
  vpMe me_;  ///< the masks of params_.me, built once per settings
  SupportBound support_bound_;  ///< params_.status.support_angle_deg's test, once per settings
  FaceVisibility face_visibility_;
  FaceVisibility faces_before_;  ///< face_visibility_ before this frame, for a retry
  Se3 camera_from_model_;
  MotionModel motion_;
  EdgeIdBuffer edge_ids_;
  EdgeIdSource* edge_id_source_ = nullptr;
  StepObserver* step_observer_ = nullptr;
  /// The grey frame; on demand, only the current frame's search boxes are up to date. Sized at
  /// the first frame whose own bytes are not the grey image: a grey8 camera's tracker holds none.
  vpImage<unsigned char> grey_;
  BoxGreyScaler grey_boxes_;
  /// Borrows the frame's own grey bytes (grey_in_place) during track only.
  vpImage<unsigned char> grey_in_place_;
  // Each frame's points, matches and pose buffers, kept so that a frame allocates nothing once
  // they have grown to the largest frame seen.
  std::vector<ControlPoint> visible_;  ///< the sampled control points, then the visible ones among them
  std::vector<PixelBox> read_boxes_;  ///< per visible point, the pixels its moving-edge search reads
  std::vector<EdgeMatch> matches_;
  PoseWorkspace pose_workspace_;
  DriftWorkspace drift_workspace_;
  RowTimes row_times_;  ///< a rolling shutter's control points as sampled, before their rows' times
  ContrastMemory contrast_memory_;  ///< the last trusted frame's edge contrasts
  std::vector<real> references_;    ///< per visible point, its remembered contrast or 0
  std::vector<unsigned char> borrowed_;  ///< per visible point, nonzero: its reference is its primitive's
  bool started_ = false;            ///< a frame has been trusted since the start or the last reset
  bool start_is_guess_ = false;     ///< the last reset's StartPose was kGuess
  StatusStatistics status_statistics_;  ///< what a tracked frame looks like on this scene
  /// The visible points at the solved pose (judge), where shares_projections().
  ProjectedPoints solved_pixels_;
  Se3 solved_pixels_pose_;  ///< the pose solved_pixels_ were projected with

 private:
  /// The grey step: converts what the moving edges will read (read_boxes_) and returns the image
  /// they read.
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
  /// A frame that would sample more control points than limits_ allow: lost, nothing searched.
  void over_limit(FrameResult& result) {
    visible_.clear();
    read_boxes_.clear();
    matches_.clear();
    result.points_sampled = 0;
    result.points_matched = 0;
    result.measures = FrameMeasures{};
    result.status = TrackingStatus::kLost;
    result.reason = StatusReason::kOverLimit;
  }
  /// The status measures of the attempt from `start` searching `range` and the rule's judgement.
  void judge(const vpImage<unsigned char>& grey, const Se3& start, unsigned range, std::uint64_t saturations,
             FrameResult& result);
  /// A rolling shutter's frame, solved from the last trusted poses' velocity, is solved again
  /// from `start` with the velocity from the last trusted pose to `solution` (rolling_shutter.h).
  void resolve_at_own_velocity(const Se3& start, const PoseParams& pose_params, PoseSolution& solution);
  /// The drift check (drift_check.h) of the frame's solution: taken or reported as its setting says.
  /// Returns whether the frame is to be reported drifted.
  bool check_for_drift(const vpImage<unsigned char>& grey, const Se3& start, const PoseParams& pose_params,
                       PoseSolution& solution);
  /// The motion model and the contrast memory take the frame's result; the next frame's start.
  void conclude(FrameResult& result);
  /// solved_pixels_ when judge projected the visible points with `solved` (the last attempt's
  /// pose), else null: the contrast memory then projects the matches' points.
  const ProjectedPoints* projected_matches(const Se3& solved) const;
  /// Whether the status measures and the contrast memory share one transform of each visible
  /// point at the solved pose (solved_pixels_): in floating point, and through a lens (a
  /// projection is dear); fixed point's targets keep the RAM (the firmware's arena at cube.xml's
  /// settings has no room for it) and transform each point where it is used.
  bool shares_projections() const { return std::numeric_limits<real>::is_iec559 || camera_.distorted(); }
  /// A camera created without an image size takes the first frame's: the camera is checked
  /// with it and the image buffers sized (the one frame that allocates them).
  std::optional<Error> take_frame_size(const FrameView& frame);
};

const char* step_name(Step step) {
  switch (step) {
    case Step::kVisibleEdges: return "visible edges detection";
    case Step::kGreyScaling: return "image grey scaling";
    case Step::kMovingEdges: return "ME";
    case Step::kPose: return "pose calculation";
  }
  return "?";
}

Result<Tracker> Tracker::create(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial,
                                const TrackerParams& params) {
  return create(model, camera, initial, params, TrackerLimits{});
}

namespace {

/// Why the model or the camera exceed stated `limits`, or nothing.
std::optional<Error> check_within_limits(const EdgeModel& model, const PinholeCamera& camera,
                                         const TrackerLimits& limits) {
  if (!limits.stated()) return std::nullopt;
  if (auto problem = check_tracker_limits(limits)) return Error{"", 0, *problem};
  if (primitive_count(model) > limits.primitives)
    return Error{"", 0, "the model has " + std::to_string(primitive_count(model)) +
                            " primitives (edges, cylinder silhouettes, circles), more than the tracker's limit of " +
                            std::to_string(limits.primitives)};
  if (camera.width < 1 || camera.height < 1 || camera.width > limits.image_width ||
      camera.height > limits.image_height)
    return Error{"", 0, "the camera's image " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                            " is not within the tracker's limit of " + std::to_string(limits.image_width) + "x" +
                            std::to_string(limits.image_height)};
  return std::nullopt;
}

}  // namespace

Result<Tracker> Tracker::create(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial,
                                const TrackerParams& params, const TrackerLimits& limits) {
  if (auto problem = check_within_limits(model, camera, limits)) return *std::move(problem);
  if (auto problem = check_camera(camera)) return *std::move(problem);
  if (auto problem = check_tracked_model(model)) return *std::move(problem);
  if (auto problem = check_tracker_params(params)) return Error{"", 0, problem->message};
  if (auto problem = check_start_pose(initial)) return Error{"", 0, "the initial pose " + *problem};
  return Tracker(std::make_unique<State>(model, camera, initial, params, limits));
}

Tracker::Tracker(std::unique_ptr<State> state) : state_(std::move(state)) {}
Tracker::Tracker(const Tracker& other) : state_(std::make_unique<State>(*other.state_)) { state_->reserve_for_limits(); }
Tracker& Tracker::operator=(const Tracker& other) {
  if (this != &other) {
    state_ = std::make_unique<State>(*other.state_);
    state_->reserve_for_limits();
  }
  return *this;
}
Tracker::Tracker(Tracker&& other) noexcept = default;
Tracker& Tracker::operator=(Tracker&& other) noexcept = default;
Tracker::~Tracker() = default;

Result<FrameResult> Tracker::track(const FrameView& frame) { return state_->track(frame); }
bool Tracker::reset(const Se3& camera_from_model, StartPose start) { return state_->reset(camera_from_model, start); }
std::optional<Error> Tracker::set_params(const TrackerParams& params) {
  if (auto problem = check_tracker_params(params)) return Error{"", 0, problem->message};
  state_->set_params(params);
  return std::nullopt;
}
const TrackerParams& Tracker::params() const { return state_->params_; }
const TrackerLimits& Tracker::limits() const { return state_->limits_; }
void Tracker::set_edge_id_source(EdgeIdSource* source) { state_->edge_id_source_ = source; }
void Tracker::set_step_observer(StepObserver* observer) { state_->step_observer_ = observer; }
const Se3& Tracker::camera_from_model() const { return state_->camera_from_model_; }
const std::vector<ControlPoint>& Tracker::control_points() const { return state_->visible_; }
const std::vector<EdgeMatch>& Tracker::matches() const { return state_->matches_; }
const EdgeIdBuffer& Tracker::edge_ids() const { return state_->edge_ids_; }
const FaceVisibility& Tracker::face_visibility() const { return state_->face_visibility_; }

namespace {

size_t model_bytes(const EdgeModel& model) {
  size_t bytes = capacity_bytes(model.vertices) + capacity_bytes(model.faces) + capacity_bytes(model.triangles) +
                 capacity_bytes(model.edges) + capacity_bytes(model.cylinders) + capacity_bytes(model.circles) +
                 capacity_bytes(model.cylinder_surface) + capacity_bytes(model.cylinder_points);
  for (const Face& face : model.faces) bytes += capacity_bytes(face.vertices);
  for (const Circle& circle : model.circles) bytes += capacity_bytes(circle.rim);
  return bytes;
}

}  // namespace

TrackerMemory Tracker::memory() const {
  const State& s = *state_;
  TrackerMemory m;
  m.model = model_bytes(s.model_);
  m.edge_id_image = s.edge_ids_.image_bytes();
  m.edge_id_lines = s.edge_ids_.line_bytes();
  m.grey_image = static_cast<size_t>(s.grey_.getWidth()) * s.grey_.getHeight();
  m.control_points = capacity_bytes(s.visible_) + capacity_bytes(s.read_boxes_) +
                     capacity_bytes(s.references_) + capacity_bytes(s.borrowed_) +
                     capacity_bytes(s.solved_pixels_.in_camera) + capacity_bytes(s.solved_pixels_.pixel) +
                     capacity_bytes(s.solved_pixels_.in_front);
  m.matches = capacity_bytes(s.matches_);
  m.pose_workspace = s.pose_workspace_.heap_bytes() + s.drift_workspace_.heap_bytes() + s.row_times_.heap_bytes();
  m.contrast_memory = s.contrast_memory_.heap_bytes();
  return m;
}

Tracker::State::State(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial,
                      const TrackerParams& params, const TrackerLimits& limits)
    : model_(model),
      camera_(camera),
      params_(params),
      limits_(limits),
      me_(moving_edge_masks(params.me)),
      support_bound_(support_bound(params.status.support_angle_deg)),
      face_visibility_(model),
      faces_before_(model),
      camera_from_model_(initial),
      motion_(initial, params.motion),
      edge_ids_(camera, primitive_count(model)) {
  reserve_for_limits();
}

void Tracker::State::reserve_for_limits() {
  if (!limits_.stated()) return;  // the buffers grow to the largest frame seen
  edge_ids_.reserve_for(model_);
  const size_t points = static_cast<size_t>(limits_.control_points);
  visible_.reserve(points);
  read_boxes_.reserve(points);
  references_.reserve(points);
  borrowed_.reserve(points);
  matches_.reserve(points);
  pose_workspace_.reserve(points, camera_.distorted());
  if (drift_check_runs(params_.thin_lines)) drift_workspace_.reserve(points);
  contrast_memory_.reserve(points, static_cast<size_t>(limits_.primitives));
  if (shares_projections()) {
    solved_pixels_.in_camera.reserve(points);
    solved_pixels_.pixel.reserve(points);
    solved_pixels_.in_front.reserve(points);
  }
  if (params_.readout != real(0)) row_times_.reserve(points);
  if (limits_.colour_frames) {
    grey_.resize(static_cast<unsigned>(camera_.height), static_cast<unsigned>(camera_.width));
    grey_boxes_.reserve(points, camera_.height);
  }
}

std::optional<Error> Tracker::State::take_frame_size(const FrameView& frame) {
  if (auto problem = check_frame(frame, frame.width, frame.height)) return problem;
  PinholeCamera sized = camera_;
  sized.width = frame.width;
  sized.height = frame.height;
  if (auto problem = check_camera(sized)) return problem;
  camera_ = sized;
  edge_ids_ = EdgeIdBuffer(camera_, primitive_count(model_));
  return std::nullopt;
}

void Tracker::State::set_params(const TrackerParams& params) {
  params_ = params;
  me_ = moving_edge_masks(params.me);
  support_bound_ = support_bound(params.status.support_angle_deg);
  motion_.set_params(params.motion);
  // A rolling shutter or the drift check switched on after create takes its room now, not in a frame.
  if (limits_.stated() && params.readout != real(0)) row_times_.reserve(static_cast<size_t>(limits_.control_points));
  if (limits_.stated() && drift_check_runs(params.thin_lines))
    drift_workspace_.reserve(static_cast<size_t>(limits_.control_points));
}

const vpImage<unsigned char>& Tracker::State::grey_scale(const FrameView& frame, unsigned int& converted) {
  converted = 0;
  const unsigned height = static_cast<unsigned>(camera_.height), width = static_cast<unsigned>(camera_.width);
  if (grey_in_place(frame)) {
    // Only read through const references: the moving edges never write the grey image.
    grey_in_place_.init(const_cast<unsigned char*>(frame.row(0)), height, width);
    return grey_in_place_;
  }
  if (grey_.getHeight() != height || grey_.getWidth() != width) grey_.resize(height, width);
  if (params_.grey == GreyScaling::kWholeFrame) {
    converted = convert_to_grey(frame, PixelBox{0, 0, frame.height, frame.width}, grey_);
    return grey_;
  }
  // Only the pixels the points' read boxes cover (docs/results/me.md: against the whole frame).
  grey_boxes_.clear();
  for (const PixelBox& box : read_boxes_) grey_boxes_.add(box);
  converted = grey_boxes_.convert(frame, grey_);
  return grey_;
}

bool Tracker::State::reset(const Se3& camera_from_model, StartPose start) {
  if (check_start_pose(camera_from_model)) return false;
  start_is_guess_ = start == StartPose::kGuess;
  camera_from_model_ = camera_from_model;
  face_visibility_.reset();
  motion_.reset(camera_from_model);
  contrast_memory_.clear();
  started_ = false;
  status_statistics_.restart(start == StartPose::kGiven);
  return true;
}

Result<FrameResult> Tracker::State::track(const FrameView& frame) {
  if (camera_.width == 0 && camera_.height == 0) {
    if (auto problem = take_frame_size(frame)) return *std::move(problem);
  }
  if (auto problem = check_frame(frame, camera_.width, camera_.height)) return *std::move(problem);
  if (limits_.stated() && !limits_.colour_frames && !grey_in_place(frame))
    return Error{"", 0, "the frame is not grey8 (or a packed Y plane), and the tracker's limits hold no grey image "
                        "(TrackerLimits::colour_frames)"};
  FrameResult result;
  // After a loss, or from a guessed start, the pose is a guess: the contrasts it would assign are
  // not the edges' there, nor do the distances to it tell the good matches from the bad.
  const bool guessing = motion_.lost_last_frame() || (!started_ && start_is_guess_);
  faces_before_ = face_visibility_;
  attempt(frame, camera_from_model_, motion_.search_range(params_.me.range), guessing, result);
  // A lost frame, or an uncertain one that started from a pose the velocity moved on: the last
  // trusted pose at rest is another start. (From the trusted pose itself, a wider search on
  // clutter only finds more of it.) It is no guess once a frame was trusted: its contrasts were
  // taken there, and the first solve's weights at it widen with the median distance.
  const bool another_start = result.status == TrackingStatus::kLost ||
                             (result.status == TrackingStatus::kUncertain && motion_.predicts_motion());
  if (another_start && params_.motion.retry_from_trusted) {
    FrameResult retry;
    carry_costs(result, retry);
    face_visibility_ = faces_before_;
    attempt(frame, motion_.trusted(), motion_.retry_range(params_.me.range), !started_, retry);
    if (retry.status == TrackingStatus::kTracked &&
        (result.status == TrackingStatus::kLost || retry.pose.residual_scale < result.pose.residual_scale))
      result = retry;
    else carry_costs(retry, result);
    result.retried = true;
  }
  conclude(result);
  return result;
}

void Tracker::State::attempt(const FrameView& frame, const Se3& start, unsigned range, bool guessing, FrameResult& result) {
  const std::uint64_t saturations = fixedpoint::saturation_count();
  StepClock clock;
  begin(Step::kVisibleEdges);
  if (edge_id_source_) edge_id_source_->draw(model_, start, edge_ids_);
  else edge_ids_.render(model_, start);
  face_visibility_.update(model_, camera_, start, params_.faces);
  SamplingParams sampling = sampling_params(params_);
  sampling.max_points = static_cast<size_t>(limits_.control_points);
  if (sample_control_points(model_, camera_, start, sampling, face_visibility_, visible_) > 0) {
    over_limit(result);
    end(Step::kVisibleEdges);
    clock.lap(Step::kVisibleEdges, result);
    return;
  }
  keep_visible(visible_, edge_ids_);
  row_times_.move(visible_, camera_, start, motion_.velocity(), params_.readout);
  if (guessing) {
    references_.assign(visible_.size(), real(0));
    borrowed_.assign(visible_.size(), 0);
  } else {
    contrast_memory_.references(visible_, camera_, start, params_.me.sample_step, references_, borrowed_);
  }
  end(Step::kVisibleEdges);
  clock.lap(Step::kVisibleEdges, result);
  begin(Step::kGreyScaling);
  unsigned int converted = 0;
  me_search_boxes(visible_, me_, range, read_boxes_);
  const vpImage<unsigned char>& grey = grey_scale(frame, converted);
  result.grey_pixels += converted;
  end(Step::kGreyScaling);
  clock.lap(Step::kGreyScaling, result);
  begin(Step::kMovingEdges);
  // Until a frame is trusted after the start, the contrasts where the given pose puts the edges.
  if (!started_ && !guessing) contrasts_at_points(grey, visible_, me_, references_);
  search_moving_edges(grey, visible_, me_, range, params_.hypotheses, matches_, &references_, &borrowed_);
  // Before the pose step: a thin dark line beside an edge passes the contrast test (#27).
  if (params_.thin_lines.enabled) reject_thin_line_matches(grey, matches_, params_.thin_lines);
  end(Step::kMovingEdges);
  clock.lap(Step::kMovingEdges, result);
  begin(Step::kPose);
  PoseParams pose_params = params_.pose;
  // A guessed start's own distances still weigh the first solve: Tukey's c grows with their
  // median, so a start some pixels off keeps the matches near it while a strongest edge on the
  // clutter beyond stands out. A prediction after a loss is no start near anything.
  pose_params.weigh_at_start = !guessing || (start_is_guess_ && !started_ && !motion_.lost_last_frame());
  // The drift check's gate reads the first solve's rows at the start (drift_check.h).
  pose_workspace_.start_rows = drift_check_runs(params_.thin_lines) ? &drift_workspace_.start_rows : nullptr;
  result.pose = solve_pose(matches_, camera_, start, pose_params, pose_workspace_);
  resolve_at_own_velocity(start, pose_params, result.pose);
  const bool drifted = check_for_drift(grey, start, pose_params, result.pose);
  end(Step::kPose);
  clock.lap(Step::kPose, result);
  result.points_sampled = static_cast<int>(visible_.size());
  result.points_matched = static_cast<int>(matches_.size()) - result.pose.outliers;
  judge(grey, start, range, saturations, result);
  if (drifted && result.status == TrackingStatus::kTracked) {
    result.status = TrackingStatus::kUncertain;
    result.reason = StatusReason::kDrift;
  }
  grey_in_place_.init(nullptr, 0, 0);  // the frame is the caller's: nothing may point into it after track
}

void Tracker::State::resolve_at_own_velocity(const Se3& start, const PoseParams& pose_params, PoseSolution& solution) {
  if (params_.readout == real(0) || !solution.solved || is_zero(motion_.velocity()) || motion_.lost_last_frame()) return;
  const Twist own = (solution.camera_from_model * motion_.trusted().inverse()).log();
  if (!row_times_.again(visible_, matches_, camera_, start, own, params_.readout)) return;
  PoseSolution second = solve_pose(matches_, camera_, start, pose_params, pose_workspace_);
  second.evaluations += solution.evaluations;
  second.iterations += solution.iterations;
  if (second.solved) solution = second;  // else the first solve's pose stands
}

bool Tracker::State::check_for_drift(const vpImage<unsigned char>& grey, const Se3& start, const PoseParams& pose_params,
                                     PoseSolution& solution) {
  const ThinLineParams& lines = params_.thin_lines;
  if (!drift_check_runs(lines) || !solution.solved) return false;
  // Drift is a trusted track's: a detected start not yet confirmed, or a prediction after a
  // loss, is the status rule's to confirm or refute (a correction could keep a wrong one alive).
  if (status_statistics_.phase() == StatusStatistics::Phase::kUnconfirmed || motion_.lost_last_frame()) return false;
  const DriftVerdict verdict = check_drift(grey, matches_, solution, model_, camera_, start, pose_params, lines,
                                           params_.status.edge_location_px, pose_workspace_, drift_workspace_);
  if (!verdict.drifted) return false;
  if (lines.check == DriftAction::kReport) return true;
  // Corrected: the second solve's pose is the frame's; its matches stay all the moving edges
  // found, counted at that pose.
  const int evaluations = solution.evaluations + verdict.second.evaluations;
  const int iterations = solution.iterations + verdict.second.iterations;
  solution = verdict.second;
  solution.evaluations = evaluations;
  solution.iterations = iterations;
  solution.outliers = mark_outliers_at(matches_, camera_, solution.camera_from_model, solution.residual_scale, pose_params);
  return false;
}

void Tracker::State::judge(const vpImage<unsigned char>& grey, const Se3& start, unsigned range,
                           std::uint64_t saturations, FrameResult& result) {
  FrameMeasures& m = result.measures;
  m.visible = result.points_sampled;
  m.matched = static_cast<int>(matches_.size());
  m.kept = result.points_matched;
  m.solved = result.pose.solved;
  m.matched_share = m.visible > 0 ? real(m.kept) / real(m.visible) : real(0);
  m.inlier_share = m.matched > 0 ? real(m.kept) / real(m.matched) : real(0);
  m.residual_scale = result.pose.residual_scale;
  const Se3& solved = result.pose.camera_from_model;
  // Each point at the solved pose once, for the measures and the contrast memory.
  const ProjectedPoints* projected = nullptr;
  if (shares_projections()) {
    project_points(visible_, camera_, solved, solved_pixels_);
    solved_pixels_pose_ = solved;
    projected = &solved_pixels_;
  }
  m.correction_px = largest_normal_shift(visible_, camera_, solved, projected);
  const Se3 change = solved * start.inverse();
  m.translation_change_mm = to_millimetres(norm(solved.translation() - start.translation()));
  m.rotation_change_deg = real(kDegreesPerRadian) * norm(rotation_log(change.rotation()));
  m.range = range;
  const real sigma = std::max(m.residual_scale, params_.status.edge_location_px);
  m.pose_uncertainty_px =
      pose_uncertainty_px(matches_, model_, camera_, solved, sigma, params_.pose.tukey_c, params_.pose.tukey_floor);
  m.saturations = fixedpoint::saturation_count() - saturations;
  m.after_loss = motion_.lost_last_frame();
  const EdgeSupport support =
      edge_support(grey, visible_, read_boxes_, camera_, solved, params_.status.gradient_floor, support_bound_,
                   projected);
  m.support_share = m.visible > 0 ? real(support.supported) / real(m.visible) : real(0);
  m.gradient_angle_deg = support.mean_angle_deg;
  const FrameStatus judged =
      judge_frame(m, params_.status, params_.pose.min_points, status_statistics_.bounds(params_.status));
  result.status = judged.status;
  result.reason = judged.reason;
}

void Tracker::State::conclude(FrameResult& result) {
  if (result.status == TrackingStatus::kLost) {
    result.camera_from_model = camera_from_model_;
    motion_.lose(model_, camera_);
  } else {
    const Se3& solved = result.pose.camera_from_model;
    result.camera_from_model = solved;
    motion_.trust(solved, model_, camera_, params_.me.range);
    contrast_memory_.remember(matches_, camera_, solved, params_.status.tracked_scale_px, projected_matches(solved));
    started_ = true;
  }
  status_statistics_.add(result.measures, result.status, params_.status);
  camera_from_model_ = motion_.prediction();
}

const ProjectedPoints* Tracker::State::projected_matches(const Se3& solved) const {
  const bool current = shares_projections() && same_bits(solved, solved_pixels_pose_) &&
                       solved_pixels_.in_front.size() == visible_.size();
  return current ? &solved_pixels_ : nullptr;
}

}  // namespace edgetrack
