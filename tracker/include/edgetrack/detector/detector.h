// SPDX-License-Identifier: BSD-3-Clause
/// Finding the model in a frame with no pose given: LINE-2D matching of the templates
/// (template_set.h) on the downscaled grey frame, then the best matches refined by the
/// tracker's own moving edges and robust pose solve; the refined pose that explains the most of
/// the image's edges wins, and a frame where none explains enough is "not found".
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/detector/gradient_orientations.h"
#include "edgetrack/detector/response_maps.h"
#include "edgetrack/detector/template_matching.h"
#include "edgetrack/detector/template_set.h"
#include "edgetrack/result.h"
#include "edgetrack/tracker.h"

namespace edgetrack {

struct DetectorParams {
  OrientationParams orientations;
  /// T: orientations spread over T x T pixels and the grid step of the sliding window
  /// (downscaled pixels). 4 at half resolution tolerates 8 full-resolution pixels.
  int spread = 4;
  MatchParams matching;
  /// Tracker frames run on the same image from each candidate, each starting afresh from the
  /// last one's pose (Tracker::reset, so each searches twice the configured range): first
  /// `wide_iterations` with the moving edges' range set to `wide_range` (a match's pose can be
  /// 20 degrees and several pixels off: the nearest template's), then `refine_iterations` with
  /// the tracking settings' own range.
  int wide_iterations = 4;
  unsigned wide_range = 8;
  int refine_iterations = 4;
  /// Found: the last refining frame is tracked and the robust solve kept at least this share of
  /// the visible control points. A wrong pose over clutter keeps under half (tracking_status.h's
  /// few-matched rule); a right one most.
  real min_kept_share = real(0.7);
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
};

struct Detection {
  bool found = false;
  Se3 camera_from_model;  ///< the winner's refined pose (meaningful when found)
  real score{0};          ///< the winner's kept share, 0 when no candidate
  real match_share{0};    ///< the winner's template score share
  int template_index = -1;
  std::vector<RefinedCandidate> refined;  ///< every candidate refined, in the order tried
};

class Detector {
 public:
  /// Checks that `templates` were made for this model and this camera.
  static Result<Detector> create(const EdgeModel& model, const PinholeCamera& camera, TemplateSet templates,
                                 const DetectorParams& params, const TrackerParams& tracking);

  /// Finds the model in one RGB565 frame of the camera's size.
  Detection detect(const uint16_t* rgb565);

  /// The template matches of the last frame, best first.
  const std::vector<TemplateMatch>& matches() const { return matches_; }
  const TemplateSet& templates() const { return templates_; }
  const DetectorParams& params() const { return params_; }

 private:
  Detector(TemplateSet templates, const DetectorParams& params, Tracker wide, Tracker tracker);
  /// The matching half: grey, downscale, orientations, spreading, response maps, matches.
  void match(const uint16_t* rgb565);
  /// The trackers run from one match's pose.
  RefinedCandidate refine(const uint16_t* rgb565, const TemplateMatch& match);
  /// `iterations` frames of `tracker` from candidate.camera_from_model; false when lost twice in a row.
  bool run_frames(Tracker& tracker, const uint16_t* rgb565, int iterations, RefinedCandidate& candidate);

  TemplateSet templates_;
  DetectorParams params_;
  Tracker wide_;  ///< the tracking settings with the range widened
  Tracker tracker_;
  std::vector<uint8_t> grey_;
  std::vector<uint8_t> small_;
  std::vector<uint8_t> scratch_;
  OrientationImage orientations_;
  OrientationImage spread_;
  ResponseMaps maps_;
  std::vector<uint16_t> scores_;
  std::vector<std::vector<TemplateMatch>> per_distance_;
  std::vector<TemplateMatch> matches_;
};

/// Checks the detector's parameters; an Error names the first one out of its range.
Result<bool> check_detector_params(const DetectorParams& params);

}  // namespace edgetrack
