// SPDX-License-Identifier: BSD-3-Clause
/// The detector: template matching, then refinement by the tracker.
#include "edgetrack/detector/detector.h"

#include <utility>

#include "edgetrack/detector/template_io.h"
#include "visp3/core/vpImageConvert.h"

namespace edgetrack {

namespace {

bool acceptable(const RefinedCandidate& c, const DetectorParams& params) {
  return c.status == TrackingStatus::kTracked && c.kept_share >= params.min_kept_share;
}

/// Better: acceptable over not, then more control points kept (a pose too far away, whose
/// smaller image lines up with a part of the object's edges, keeps as large a share of fewer
/// points), then the smaller residual scale.
bool better(const RefinedCandidate& a, const RefinedCandidate& b, const DetectorParams& params) {
  const bool aa = acceptable(a, params), ba = acceptable(b, params);
  if (aa != ba) return aa;
  if (a.kept != b.kept) return a.kept > b.kept;
  return a.residual_scale < b.residual_scale;
}

}  // namespace

Result<bool> check_detector_params(const DetectorParams& p) {
  auto bad = [](const std::string& what) { return Error{"", 0, "detector parameter out of range: " + what}; };
  if (p.orientations.min_magnitude < 1 || p.orientations.min_magnitude > 1442)
    return bad("the gradient threshold must be 1 to 1442");
  if (p.orientations.min_agreeing < 1 || p.orientations.min_agreeing > 9) return bad("agreeing pixels must be 1 to 9");
  if (p.spread < 1 || p.spread > 16) return bad("the spread T must be 1 to 16");
  if (p.matching.max_candidates < 1 || p.matching.max_candidates > 100) return bad("candidates must be 1 to 100");
  if (!(p.matching.min_share >= real(0)) || p.matching.min_share > real(1)) return bad("the match share must be 0 to 1");
  if (p.refine_iterations < 1 || p.refine_iterations > 50) return bad("refining frames must be 1 to 50");
  if (p.wide_iterations < 0 || p.wide_iterations > 50) return bad("wide refining frames must be 0 to 50");
  if (p.wide_range < 1 || p.wide_range > 64) return bad("the wide range must be 1 to 64 px");
  if (!(p.min_kept_share >= real(0)) || p.min_kept_share > real(1)) return bad("the kept share must be 0 to 1");
  return true;
}

Result<Detector> Detector::create(const EdgeModel& model, const PinholeCamera& camera, TemplateSet templates,
                                  const DetectorParams& params, const TrackerParams& tracking) {
  auto checked = check_detector_params(params);
  if (!checked.ok()) return checked.error();
  if (templates.model_fingerprint != model_fingerprint(model))
    return Error{"", 0, "the templates were made for another model (" + templates.model_fingerprint + ", this one is " +
                            model_fingerprint(model) + ")"};
  if (camera_description(templates.camera) != camera_description(camera))
    return Error{"", 0, "the templates were made for another camera (" + camera_description(templates.camera) +
                            ", this one is " + camera_description(camera) + ")"};
  const ModelExtent extent = model_extent(model);
  const Se3 start(Mat33::identity(), Vec3{real(0), real(0), real(4) * extent.radius + real(0.1)} - extent.centre);
  Result<Tracker> tracker = Tracker::create(model, camera, start, tracking);
  if (!tracker.ok()) return tracker.error();
  TrackerParams wide_tracking = tracking;
  wide_tracking.me.setRange(params.wide_range);
  Result<Tracker> wide = Tracker::create(model, camera, start, wide_tracking);
  if (!wide.ok()) return wide.error();
  return Detector(std::move(templates), params, std::move(wide).value(), std::move(tracker).value());
}

Detector::Detector(TemplateSet templates, const DetectorParams& params, Tracker wide, Tracker tracker)
    : templates_(std::move(templates)), params_(params), wide_(std::move(wide)), tracker_(std::move(tracker)) {}

void Detector::match(const uint16_t* rgb565) {
  const PinholeCamera& camera = templates_.camera;
  grey_.resize(static_cast<size_t>(camera.width) * camera.height);
  vpImageConvert::RGB565ToGrey(rgb565, grey_.data(), static_cast<unsigned>(grey_.size()));
  const int factor = templates_.params.downscale;
  const uint8_t* image = grey_.data();
  if (factor > 1) {
    downscale_grey(grey_.data(), camera.width, camera.height, factor, small_);
    image = small_.data();
  }
  quantise_orientations(image, camera.width / factor, camera.height / factor, params_.orientations, scratch_,
                        orientations_);
  spread_orientations(orientations_, params_.spread, scratch_, spread_);
  maps_.compute(spread_, params_.spread);
  match_templates(templates_, maps_, params_.matching, scores_, per_distance_, matches_);
}

bool Detector::run_frames(Tracker& tracker, const uint16_t* rgb565, int iterations, RefinedCandidate& candidate) {
  int lost_in_a_row = 0;
  for (int k = 0; k < iterations; ++k) {
    if (!tracker.reset(candidate.camera_from_model)) return false;
    const FrameResult frame = tracker.track(rgb565);
    candidate.status = frame.status;
    candidate.visible = frame.measures.visible;
    candidate.kept = frame.measures.kept;
    candidate.kept_share = frame.measures.matched_share;
    candidate.residual_scale = frame.measures.residual_scale;
    if (frame.status == TrackingStatus::kLost) {
      if (++lost_in_a_row == 2) return false;
      continue;
    }
    lost_in_a_row = 0;
    candidate.camera_from_model = frame.camera_from_model;
  }
  return true;
}

RefinedCandidate Detector::refine(const uint16_t* rgb565, const TemplateMatch& match) {
  RefinedCandidate candidate;
  candidate.match = match;
  candidate.camera_from_model = pose_of_match(templates_, match, params_.spread);
  if (run_frames(wide_, rgb565, params_.wide_iterations, candidate))
    run_frames(tracker_, rgb565, params_.refine_iterations, candidate);
  return candidate;
}

Detection Detector::detect(const uint16_t* rgb565) {
  Detection detection;
  match(rgb565);
  for (const TemplateMatch& m : matches_) detection.refined.push_back(refine(rgb565, m));
  const RefinedCandidate* best = nullptr;
  for (const RefinedCandidate& c : detection.refined)
    if (!best || better(c, *best, params_)) best = &c;
  if (!best) return detection;
  detection.camera_from_model = best->camera_from_model;
  detection.score = best->kept_share;
  detection.match_share = best->match.share;
  detection.template_index = best->match.template_index;
  detection.found = acceptable(*best, params_);
  return detection;
}

}  // namespace edgetrack
