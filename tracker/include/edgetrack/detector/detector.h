// SPDX-License-Identifier: BSD-3-Clause
/// Finding the model in a frame with no pose given: LINE-2D matching of the templates
/// (template_set.h) on the downscaled grey frame, then the best matches refined by the
/// tracker's own moving edges and robust pose solve; the refined pose that explains the most of
/// the image's edges wins, and a frame where none explains enough is "not found".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "edgetrack/detector/gradient_orientations.h"
#include "edgetrack/detector/response_maps.h"
#include "edgetrack/detector/template_matching.h"
#include "edgetrack/detector/template_set.h"
#include "edgetrack/frame_view.h"
#include "edgetrack/result.h"
#include "edgetrack/tracker.h"

namespace edgetrack {

struct DetectorParams {
  OrientationParams orientations;
  /// T: orientations spread over T x T pixels and the grid step of the sliding window
  /// (downscaled pixels). 4 at half resolution tolerates 8 full-resolution pixels.
  int spread = 4;
  MatchParams matching;
  /// Tracker frames run on the same image from each candidate, as a tracker on a still scene
  /// (no velocity predicted; the first frame from the match's pose as a guess, each next one
  /// from the last, with the contrasts and weights a tracked frame gives it):
  /// `refine_iterations` with the tracking settings' range; when that does not end in an
  /// acceptable pose, again from the match: `wide_iterations` with the moving edges' range set
  /// to `wide_range`, then `refine_iterations` with the tracking range. A match's pose is the
  /// nearest template's, up to the grid's reach off (14 degrees, docs/results/detection.md); a
  /// turn that large moves the outline of a model some 75 px in radius in the image (60 mm
  /// across at 150 mm) by up to 18 px, which a first frame's search (twice the range) reaches
  /// from range 10 and not from 6 (12 px, about 9 degrees). The better of the two, unless
  /// already confident (it ends the search as it is), is
  /// run again for `given_iterations` from its pose as a given one (Tracker::StartPose::kGiven:
  /// the contrasts taken where it puts the model's edges, the first solve weighted at it), which
  /// is kept when better: the guessed runs take each point's strongest edge in the range, and
  /// beside a parallel edge or on textured clutter they settle a few pixels off even from the
  /// true pose, where a given start stays. The pose kept,
  /// when acceptable, settles with `fine_iterations` at `fine_range` (its pose taken, its
  /// status not: a search that narrow finds edges near any pose): near the optimum a search as
  /// wide as the tracking range's start (twice the range) reaches neighbouring edges (parallel
  /// inner edges, background lines) that pull a single frame's pose away from it.
  int refine_iterations = 6;
  int wide_iterations = 4;
  unsigned wide_range = 10;
  int fine_iterations = 8;
  unsigned fine_range = 2;
  int given_iterations = 6;
  /// A run stops before its last frame once a tracked frame moved no control point farther
  /// along its normal than this (pixels): the pose has settled, and the next frame on the same
  /// image would start where this one ended.
  real settled_px = real(0.25);
  /// Control points of the refining runs every this many pixels along the edges: one image has
  /// to fix all six degrees of freedom, and an inner edge the light leaves faint holds only a
  /// few points at the tracking step (10), too few to hold the pose against the outline's slack.
  real refine_sample_step = real(5);
  /// The screening only ranks the matches by the control points they keep, which a third of
  /// the tracking step's points do as well.
  real screen_sample_step = real(15);
  /// Robust rounds per frame (PoseParams::robust_rounds) of the refining and screening runs.
  /// A run's next frame starts its first solve weighted at this one's pose, so the frames carry
  /// the re-weighting on; the screening only ranks, so one round does. A refining frame takes more
  /// than a tracked one: its start is a template's pose, degrees off, and each round is one LM
  /// step whose weights follow the pose; with more rounds a frame comes nearer its optimum, so
  /// a run settles (settled_px) in fewer frames.
  int refine_robust_rounds = 8;
  int screen_robust_rounds = 1;
  /// A refining frame's robust rounds end once one moved no control point farther than this
  /// (pixels; PoseParams::rounds_settled_px): on a still image the rounds reach the frame's
  /// weighted optimum well before the last one once the run nears its pose, and the rest only
  /// repeat it. A hundredth of a pixel is far below what the moving edges resolve.
  real refine_rounds_settled_px = real(0.01);
  /// The screening and refining runs' pose solver (PoseParams::solver): the normal equations take
  /// fewer instructions per solve than MINPACK's QR, and a detection solves a few hundred times.
  PoseSolver solver = PoseSolver::kNormalEquations;
  /// With more than one match, each is first screened by `screen_iterations` frames at the
  /// tracking range and ranked: tracked before uncertain before lost (a screen that already fits
  /// is the likeliest to refine to a confident fit), then by the control points kept; the best
  /// `refined_candidates` are refined, best first, until one is confidently right
  /// (confident_scale_px): the screen's frames already part the matches that are near the object
  /// from the rest, at a fraction of the full cost, so that the later candidates cost only where
  /// the first ones failed, and a budget (max_points_searched) cuts only the unlikely tail.
  int screen_iterations = 3;
  int refined_candidates = 8;
  /// Before screening, a match whose pose is within `suppress_deg` of rotation and
  /// `suppress_radii` model radii of centre of a better one's is dropped (non-maximum
  /// suppression over the pose): neighbouring templates matching the same place refine to the
  /// same pose, and screening each costs frames that a different candidate could use. 16 degrees
  /// is a step of the sphere's directions at 2 subdivisions; a quarter of the radius is about the
  /// refinement's reach in depth (half a distance step is 5 %, a fifth of the radius at 4 radii).
  real suppress_deg = real(16);
  real suppress_radii = real(0.25);
  /// The first refined candidate that is a near miss (tracked, its support at least min_support,
  /// not confident) is refined again at once, before the other candidates, from its pose tilted
  /// by this many degrees about the camera's x and y axes through the model's centre (4 starts;
  /// each only the tracking-range run and the settling), until one is confidently right; when
  /// none is confident after all the others, the best one (the detection's order: acceptable
  /// first, then the most control points kept; not lost, its support at least min_support) is,
  /// unless it is that near miss. A still image's
  /// refinement can settle in a neighbouring minimum a few degrees off (a parallel edge a face's
  /// thickness away taken for the model's, a tilt the outline hardly shows), where it may even
  /// be acceptable: right poses fit within a quarter pixel, and most acceptable ones that do
  /// not are a few degrees off. A match is up to half a step of the sphere's directions off its
  /// view (the step: 16 degrees at 2 subdivisions), and the refinement reaches that far, so
  /// half a step to one side is within its reach of the truth's side. 0: no restarts.
  real restart_tilt_deg = real(8);
  /// Found: the last refining frame is tracked and the robust solve kept at least this share of
  /// the visible control points. A wrong pose over clutter keeps under half (tracking_status.h's
  /// few-matched rule); a right one most.
  real min_kept_share = real(0.7);
  /// Found also needs this support (RefinedCandidate::support). Right poses of the generated
  /// cube and wood toy had 0.5 to 0.95 (an inner edge the light leaves without contrast has
  /// none), so this only refuses a pose the image's gradients do not show at all.
  real min_support = real(0.4);
  /// Found also needs the refined candidate's robust residual scale (px) at most this. A
  /// tracked frame may have up to a pixel (StatusParams::tracked_scale_px): edges move and blur
  /// between frames. A still image refined to convergence keeps only the edges' localisation:
  /// a pose whose whole edges lie half a pixel off (an out-of-plane tilt the outline hardly
  /// shows, a neighbouring edge taken for the model's) is wrong, not imprecise.
  real max_residual_scale_px = real(0.5);
  /// Candidates are refined best first until one is found with a residual scale at most this
  /// (px): the moving edges' sites within their pixel of the model's lines, a fit that no other
  /// candidate's could better. A confident candidate wins over an acceptable one that is not.
  real confident_scale_px = real(0.25);
  /// A confident fit also keeps at least this share of the visible control points: a pose
  /// nearer or farther, or turned, whose image lines up with a part of the object's edges fits
  /// that part as closely and leaves the rest unexplained (wrong ones of the generated cube kept
  /// 0.7 to 0.8), while a right one keeps all but the points of an edge the light leaves faint
  /// (0.8 to 1 on nearly every right pose of the cube and the wood toy).
  real confident_kept_share = real(0.8);
  /// The detection's work budget, in control points the screening and refining frames of one
  /// detection may search (Detection::points_searched) on a QVGA frame (320 x 240); a detection
  /// frame of another size gets it scaled by its pixels (Detector::points_budget; 0: no limit).
  /// A detection's cost past the matching is about proportional to its points, and without a
  /// limit a frame whose matches all fail costs every candidate's full schedule. The default
  /// bounds a QVGA detection on the PXA270 to 300 M guest instructions (0.7 s at 624 MHz): the
  /// matching about 50 M, then about 30-36 k a point on the mean but up to about 47 k in the
  /// costliest detections (docs/results/detection.md), so 5000 points and the frame that takes
  /// it over stay under. Scaled by the pixels, the budget keeps the detection's worst cost in
  /// proportion to the frame's own (the grey conversion and the matching cost per pixel): a
  /// frame twice as wide shows each candidate's edges twice as long (twice the points a frame),
  /// and its default range of distances (the model spanning a tenth to the whole of the
  /// shorter side) reaches nearer candidates whose screening frames cost the more.
  /// No frame starts once it is spent (the last one started may take it over by its own visible
  /// points). The search order (screen, search) puts the likely candidates first, so the budget
  /// cuts the tail; a detection it cut short is found only with a confident candidate (a fit no
  /// later one could better), never with a merely acceptable pose the rest of the search might
  /// have replaced: "not found", and the next frame is detected on again.
  int max_points_searched = 5000;
};

/// One candidate after refinement.
struct RefinedCandidate {
  TemplateMatch match;
  Se3 camera_from_model;  ///< refined
  TrackingStatus status = TrackingStatus::kLost;
  int visible = 0;  ///< visible control points of the last refining frame
  int kept = 0;     ///< of those, the ones the robust solve kept
  real kept_share{0};
  real residual_scale{0};
  /// Of the visible control points at the refined pose, the share whose image pixel (downscaled,
  /// or one of its 8 neighbours) has their edge's orientation bin: the image's own gradients
  /// confirming the pose, independently of the moving edges' search.
  real support{0};
};

struct Detection {
  bool found = false;
  Se3 camera_from_model;  ///< the winner's refined pose (meaningful when found)
  real score{0};          ///< the winner's kept share, 0 when no candidate
  real match_share{0};    ///< the winner's template score share
  int template_index = -1;
  std::vector<RefinedCandidate> refined;  ///< every candidate refined, in the order tried
  /// Control points of every screening and refining frame: a detection's guest cost past the
  /// matching is about proportional to it (docs/results/detection.md).
  int points_searched = 0;
  /// Screening and refining frames run: with a budget (DetectorParams::max_points_searched) at
  /// most one past the frame that spent it.
  int frames = 0;
  /// The budget ended the search with no confident candidate: then not found, whatever the best
  /// candidate's acceptance (DetectorParams::max_points_searched).
  bool cut_short = false;
};

class Detector {
 public:
  /// Checks that `templates` were made for this model and this camera (the full-size camera of
  /// the frames detect reads). Frames above kMaxDetectionSide on their shorter side are detected
  /// on a copy reduced by detection_reduction (template_set.h): the refining trackers run at the
  /// templates' detection_camera() with `tracking` as given, and the pose found is the
  /// full-size camera's.
  static Result<Detector> create(const EdgeModel& model, const PinholeCamera& camera, TemplateSet templates,
                                 const DetectorParams& params, const TrackerParams& tracking);

  /// Finds the model in one frame of the camera's (full) size, in any layout (frame_view.h); an
  /// Error when check_frame refuses it.
  Result<Detection> detect(const FrameView& frame);

  /// The refinement alone (the runs a match's pose gets in detect) from `start` on one frame:
  /// how far the refinement's own basin reaches (tests, benchmarks).
  Result<RefinedCandidate> refine_from(const FrameView& frame, const Se3& start);

  /// The template matches of the last frame, best first.
  const std::vector<TemplateMatch>& matches() const { return matches_; }
  const TemplateSet& templates() const { return templates_; }
  const DetectorParams& params() const { return params_; }
  /// DetectorParams::max_points_searched scaled from QVGA to the detection frame's pixels (the
  /// templates' detection_camera()); 0: no limit.
  int points_budget() const { return points_budget_; }

 private:
  Detector(TemplateSet templates, const DetectorParams& params, Tracker screen, Tracker wide, Tracker tracker,
           Tracker fine);
  /// The matching half: grey, reduction, downscale, orientations, spreading, response maps, matches.
  void match(const FrameView& frame);
  /// The grey frame of detecting_'s size that match made, which the refining trackers read in
  /// place (no frame converted again).
  FrameView detection_frame() const;
  /// The candidates refined in the order that puts the likely ones first, so that a budget
  /// (DetectorParams::max_points_searched) cuts only the tail; each kept in detection.refined.
  /// Pass 1, the screened matches best first: the tracking-range run, then finish; the first
  /// near miss's tilted restarts right after it. Pass 2: refine_wide for the candidates pass 1
  /// left unacceptable. Then the restarts from the best candidate, unless it is that near miss.
  /// Ends as soon as a candidate is confident or the budget is spent.
  void search(const FrameView& frame, Detection& detection);
  /// The budget is spent or the last candidate refined is confident.
  bool search_over(const Detection& detection) const;
  /// From `start`: the tracking-range run, then finish (lost when the run was).
  RefinedCandidate refine_near(const FrameView& frame, const TemplateMatch& match, const Se3& start);
  /// From `start`: the widened-range run, the tracking-range run, then finish (lost when a run was).
  RefinedCandidate refine_wide(const FrameView& frame, const TemplateMatch& match, const Se3& start);
  /// A run's end: again from its pose as a given one (kept when better), then settle.
  void finish(const FrameView& frame, RefinedCandidate& candidate);
  /// The tracking-range run alone, then settle: a restart's (restart_tilted).
  RefinedCandidate refine_tilted(const FrameView& frame, const TemplateMatch& match, const Se3& start);
  /// True when `candidate`'s pose puts no vertex of the model farther than the tracking range
  /// from where a not-lost one of `earlier` puts it: the same edges are in reach of both, so the
  /// rest of the refinement would take this one where it took that one.
  bool same_as_earlier(const RefinedCandidate& candidate, const std::vector<RefinedCandidate>& earlier) const;
  /// `candidate` settled by the narrow range when acceptable.
  void settle(const FrameView& frame, RefinedCandidate& candidate);
  /// More refinements of `base` from tilted starts (DetectorParams::restart_tilt_deg), until one
  /// is confident or the budget is spent; each added to detection.refined.
  void restart_tilted(const FrameView& frame, Detection& detection, const RefinedCandidate& base);
  /// Tracked, supported by the image's gradients (min_support) and not confident: a candidate
  /// whose tilted restarts are worth running first.
  bool near_miss(const RefinedCandidate& candidate) const;
  /// The best candidate of `detection` that is not lost and supported (min_support); none when
  /// one is confident.
  const RefinedCandidate* restart_base(const Detection& detection) const;
  /// matches_ without the ones near a better one's pose (DetectorParams::suppress_deg).
  void suppress_neighbours();
  /// The matches worth refining (refined_candidates at most), each screened by a few frames and
  /// ranked: tracked, uncertain, lost, then by the control points kept.
  std::vector<TemplateMatch> screen(const FrameView& frame);
  /// candidate.support from `tracker`'s last control points.
  void measure_support(const Tracker& tracker, RefinedCandidate& candidate) const;
  /// Up to `iterations` frames of `tracker` from candidate.camera_from_model (a guess), each from
  /// the last, while the points budget lasts; false when lost twice in a row or when no frame ran.
  bool run_frames(Tracker& tracker, const FrameView& frame, int iterations, RefinedCandidate& candidate,
                  Tracker::StartPose start = Tracker::StartPose::kGuess);

  TemplateSet templates_;
  DetectorParams params_;
  Tracker screen_;   ///< the tracking settings, on a still scene
  Tracker wide_;     ///< refining: the range widened
  Tracker tracker_;  ///< refining: the tracking range
  Tracker fine_;     ///< refining: the range narrowed
  EdgeModel model_;             ///< for same_as_earlier's image shift
  unsigned tracking_range_ = 0;  ///< the tracking settings' moving-edges range, px
  PinholeCamera detecting_;     ///< the templates' detection_camera(): the refining trackers'
  std::vector<uint8_t> grey_;  ///< the frame in grey, row after row
  std::vector<uint8_t> reduced_;  ///< grey_ reduced to detecting_'s size, when smaller
  std::vector<uint8_t> small_;
  std::vector<uint8_t> scratch_;
  OrientationImage orientations_;
  OrientationImage spread_;
  ResponseMaps maps_;
  std::vector<uint32_t> scores_;
  std::vector<const uint32_t*> runs_;
  std::vector<std::vector<TemplateMatch>> per_distance_;
  std::vector<TemplateMatch> matches_;
  int points_budget_ = 0;    ///< points_budget()
  int points_searched_ = 0;  ///< this detection's, so far
  int frames_ = 0;           ///< this detection's, so far
  /// points_budget() is spent.
  bool budget_spent() const { return points_budget_ > 0 && points_searched_ >= points_budget_; }
};

/// A work budget of `qvga_points` control points on a QVGA frame, scaled to a detection frame of
/// `detecting`'s pixels (at least 1; 0 when `qvga_points` is 0: no limit).
int scaled_points_budget(int qvga_points, const PinholeCamera& detecting);

/// Checks the detector's parameters; an Error names the first one out of its range.
Result<bool> check_detector_params(const DetectorParams& params);

/// Sets the detector's setting `name` that a configuration (<edgetrack><detector>) or the
/// command line (--detector) may give: max_points_searched, the detection's work budget (QVGA's;
/// DetectorParams::max_points_searched). An
/// empty string when set; otherwise the problem (an unknown name, a value out of range).
std::string set_detector_param(DetectorParams& params, const std::string& name, double value);

}  // namespace edgetrack
