// SPDX-License-Identifier: BSD-3-Clause
/// The detector: template matching, then refinement by the tracker.
#include "edgetrack/detector/detector.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include "edgetrack/angles.h"
#include "edgetrack/detector/template_io.h"
#include "edgetrack/grey_conversion.h"
#include "edgetrack/motion_model.h"

namespace edgetrack {

namespace {

bool acceptable(const RefinedCandidate& c, const DetectorParams& params) {
  return c.status == TrackingStatus::kTracked && c.kept_share >= params.min_kept_share &&
         c.support >= params.min_support && c.residual_scale <= params.max_residual_scale_px;
}

/// Acceptable, fitting within DetectorParams::confident_scale_px and keeping at least
/// confident_kept_share of the visible points.
bool confident(const RefinedCandidate& c, const DetectorParams& params) {
  return acceptable(c, params) && c.residual_scale <= params.confident_scale_px &&
         c.kept_share >= params.confident_kept_share;
}

/// Better: acceptable over not, confident over not (right poses fit within the edges'
/// localisation, a few degrees off keeps whole edges that far away), then more control points
/// kept (a pose too far away, whose smaller image lines up with a part of the object's edges,
/// keeps as large a share of fewer points), then the smaller residual scale.
bool better(const RefinedCandidate& a, const RefinedCandidate& b, const DetectorParams& params) {
  const bool aa = acceptable(a, params), ba = acceptable(b, params);
  if (aa != ba) return aa;
  const bool ac = confident(a, params), bc = confident(b, params);
  if (ac != bc) return ac;
  if (a.kept != b.kept) return a.kept > b.kept;
  return a.residual_scale < b.residual_scale;
}

}  // namespace

int scaled_points_budget(int qvga_points, const PinholeCamera& detecting) {
  if (qvga_points <= 0) return 0;
  constexpr int64_t kQvgaPixels = 320 * 240;
  const int64_t pixels = static_cast<int64_t>(detecting.width) * detecting.height;
  const int64_t scaled = (static_cast<int64_t>(qvga_points) * pixels + kQvgaPixels / 2) / kQvgaPixels;
  return static_cast<int>(std::min<int64_t>(std::max<int64_t>(scaled, 1), std::numeric_limits<int>::max()));
}

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
  if (p.fine_iterations < 0 || p.fine_iterations > 50) return bad("fine refining frames must be 0 to 50");
  if (p.fine_range < 1 || p.fine_range > 64) return bad("the fine range must be 1 to 64 px");
  if (p.screen_iterations < 1 || p.screen_iterations > 50) return bad("screening frames must be 1 to 50");
  if (p.refined_candidates < 1 || p.refined_candidates > 100) return bad("refined candidates must be 1 to 100");
  if (p.max_points_searched < 0) return bad("the points budget must be 0 (none) or more");
  if (!(p.suppress_deg >= real(0)) || p.suppress_deg > real(180))
    return bad("the suppressed angle must be 0 to 180 degrees");
  if (!(p.suppress_radii >= real(0)) || p.suppress_radii > real(10))
    return bad("the suppressed distance must be 0 to 10 radii");
  if (!(p.restart_tilt_deg >= real(0)) || p.restart_tilt_deg > real(90))
    return bad("the restart tilt must be 0 to 90 degrees");
  if (!(p.settled_px >= real(0)) || p.settled_px > real(10)) return bad("the settled move must be 0 to 10 px");
  if (!(p.refine_sample_step >= real(2)) || p.refine_sample_step > real(50) || !(p.screen_sample_step >= real(2)) ||
      p.screen_sample_step > real(50))
    return bad("the refining and screening sample steps must be 2 to 50 px");
  if (p.screen_robust_rounds < 0 || p.screen_robust_rounds > 10 || p.refine_robust_rounds < 0 ||
      p.refine_robust_rounds > 10)
    return bad("the screening and refining robust rounds must be 0 to 10");
  if (!(p.refine_rounds_settled_px >= real(0)) || p.refine_rounds_settled_px > real(1))
    return bad("the refining rounds' settled move must be 0 to 1 px");
  if (p.given_iterations < 0 || p.given_iterations > 50) return bad("given refining frames must be 0 to 50");
  if (!(p.min_kept_share >= real(0)) || p.min_kept_share > real(1)) return bad("the kept share must be 0 to 1");
  if (!(p.min_support >= real(0)) || p.min_support > real(1)) return bad("the support must be 0 to 1");
  if (!(p.confident_kept_share >= p.min_kept_share) || p.confident_kept_share > real(1))
    return bad("the confident kept share must be from the least kept share to 1");
  if (!(p.confident_scale_px >= real(0)) || p.confident_scale_px > p.max_residual_scale_px ||
      p.max_residual_scale_px > real(10))
    return bad("the residual scales must be 0 <= confident <= most <= 10 px");
  return true;
}

std::string set_detector_param(DetectorParams& params, const std::string& name, double value) {
  if (name != "max_points_searched") return "'" + name + "' is not a detector setting (max_points_searched is)";
  if (!(value >= 0 && value <= 1e9) || value != static_cast<double>(static_cast<int>(value)))
    return "max_points_searched must be a whole number from 0 (no limit) to 1e9";
  params.max_points_searched = static_cast<int>(value);
  return "";
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
  // The refining trackers work at the camera detection runs at (frames above kMaxDetectionSide
  // reduced); their settings are taken as given, pixels of frames of that size.
  const PinholeCamera detecting = templates.detection_camera();
  const ModelExtent extent = model_extent(model);
  const Se3 start(Mat33::identity(), Vec3{real(0), real(0), real(4) * extent.radius + real(0.1)} - extent.centre);
  // One image, so nothing moves between its frames: no velocity is predicted; and each frame's
  // first solve is weighted at the last one's pose, so the run's frames carry the re-weighting on.
  TrackerParams screening = tracking, refining = tracking;
  screening.motion.velocity_share = refining.motion.velocity_share = real(0);
  // A candidate is no trusted start: each is judged by the fixed status bounds, learning nothing.
  screening.status.learn_frames = refining.status.learn_frames = 0;
  screening.me.sample_step = params.screen_sample_step;
  screening.pose.robust_rounds = params.screen_robust_rounds;
  refining.me.sample_step = params.refine_sample_step;
  refining.pose.robust_rounds = params.refine_robust_rounds;
  refining.pose.rounds_settled_px = params.refine_rounds_settled_px;
  screening.pose.solver = refining.pose.solver = params.solver;
  TrackerParams wide_tracking = refining, fine_tracking = refining;
  wide_tracking.me.range = params.wide_range;
  fine_tracking.me.range = params.fine_range;
  Result<Tracker> screen = Tracker::create(model, detecting, start, screening);
  if (!screen.ok()) return screen.error();
  Result<Tracker> tracker = Tracker::create(model, detecting, start, refining);
  if (!tracker.ok()) return tracker.error();
  Result<Tracker> wide = Tracker::create(model, detecting, start, wide_tracking);
  if (!wide.ok()) return wide.error();
  Result<Tracker> fine = Tracker::create(model, detecting, start, fine_tracking);
  if (!fine.ok()) return fine.error();
  Detector detector(std::move(templates), params, std::move(screen).value(), std::move(wide).value(),
                    std::move(tracker).value(), std::move(fine).value());
  detector.model_ = model;
  detector.detecting_ = detecting;
  detector.tracking_range_ = tracking.me.range;
  detector.points_budget_ = scaled_points_budget(params.max_points_searched, detecting);
  return detector;
}

Detector::Detector(TemplateSet templates, const DetectorParams& params, Tracker screen, Tracker wide, Tracker tracker,
                   Tracker fine)
    : templates_(std::move(templates)),
      params_(params),
      screen_(std::move(screen)),
      wide_(std::move(wide)),
      tracker_(std::move(tracker)),
      fine_(std::move(fine)) {}

void Detector::match(const FrameView& frame) {
  const PinholeCamera& camera = templates_.camera;
  grey_.resize(static_cast<size_t>(camera.height) * static_cast<size_t>(camera.width));
  vpImage<unsigned char> grey(grey_.data(), static_cast<unsigned>(camera.height), static_cast<unsigned>(camera.width));
  PixelBox whole;
  whole.bottom = camera.height;
  whole.right = camera.width;
  convert_to_grey(frame, whole, grey);
  // A frame above kMaxDetectionSide is reduced once, here; matching and refining read the copy.
  const int reduction = detection_reduction(camera);
  if (reduction > 1) downscale_grey(grey_.data(), camera.width, camera.height, reduction, reduced_);
  const int factor = templates_.params.downscale;
  const uint8_t* image = reduction > 1 ? reduced_.data() : grey_.data();
  if (factor > 1) {
    downscale_grey(image, detecting_.width, detecting_.height, factor, small_);
    image = small_.data();
  }
  quantise_orientations(image, detecting_.width / factor, detecting_.height / factor, params_.orientations, scratch_,
                        orientations_);
  spread_orientations(orientations_, params_.spread, scratch_, spread_);
  maps_.compute(spread_, params_.spread);
  match_templates(templates_, maps_, params_.matching, scores_, runs_, per_distance_, matches_);
  suppress_neighbours();
}

bool Detector::run_frames(Tracker& tracker, const FrameView& frame, int iterations, RefinedCandidate& candidate,
                          Tracker::StartPose start) {
  int lost_in_a_row = 0;
  if (budget_spent() || !tracker.reset(candidate.camera_from_model, start)) return false;
  for (int k = 0; k < iterations && !budget_spent(); ++k) {
    const Result<FrameResult> tracked = tracker.track(frame);
    if (!tracked.ok()) return false;
    const FrameResult& result = tracked.value();
    points_searched_ += result.measures.visible;
    ++frames_;
    candidate.status = result.status;
    candidate.visible = result.measures.visible;
    candidate.kept = result.measures.kept;
    candidate.kept_share = result.measures.matched_share;
    candidate.residual_scale = result.measures.residual_scale;
    if (result.status == TrackingStatus::kLost) {
      if (++lost_in_a_row == 2) return false;
      continue;
    }
    lost_in_a_row = 0;
    candidate.camera_from_model = result.camera_from_model;
    if (result.status == TrackingStatus::kTracked && result.measures.correction_px <= params_.settled_px) break;
  }
  measure_support(tracker, candidate);
  return true;
}

void Detector::measure_support(const Tracker& tracker, RefinedCandidate& candidate) const {
  using std::floor;
  const PinholeCamera camera = templates_.matching_camera();
  const int w = orientations_.width, h = orientations_.height;
  int supported = 0, counted = 0;
  for (const ControlPoint& p : tracker.control_points()) {
    const Vec3 c = candidate.camera_from_model * p.point_in_model;
    if (!(c.z > real(0))) continue;
    const Vec2 uv = camera.project(c);
    const int x = static_cast<int>(floor(uv.x + real(0.5))), y = static_cast<int>(floor(uv.y + real(0.5)));
    if (x < 1 || y < 1 || x + 1 >= w || y + 1 >= h) continue;
    const int bin = orientation_bin(static_cast<int32_t>(p.normal.x * real(1024)), static_cast<int32_t>(p.normal.y * real(1024)));
    uint8_t around = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) around |= orientations_.bits[static_cast<size_t>(y + dy) * w + x + dx];
    ++counted;
    supported += similarity(bin, around) == kBestSimilarity;
  }
  candidate.support = counted > 0 ? real(supported) / real(counted) : real(0);
}

bool Detector::same_as_earlier(const RefinedCandidate& candidate, const std::vector<RefinedCandidate>& earlier) const {
  for (const RefinedCandidate& c : earlier)
    if (c.status != TrackingStatus::kLost &&
        largest_image_shift(model_, detecting_, c.camera_from_model, candidate.camera_from_model) <=
            real(static_cast<int>(tracking_range_)))
      return true;
  return false;
}

RefinedCandidate Detector::refine_near(const FrameView& frame, const TemplateMatch& match, const Se3& start) {
  RefinedCandidate near;
  near.match = match;
  near.camera_from_model = start;
  if (run_frames(tracker_, frame, params_.refine_iterations, near))
    finish(frame, near);
  else
    near.status = TrackingStatus::kLost;
  return near;
}

RefinedCandidate Detector::refine_wide(const FrameView& frame, const TemplateMatch& match, const Se3& start) {
  RefinedCandidate wide;
  wide.match = match;
  wide.camera_from_model = start;
  if (params_.wide_iterations > 0 && run_frames(wide_, frame, params_.wide_iterations, wide) &&
      run_frames(tracker_, frame, params_.refine_iterations, wide))
    finish(frame, wide);
  else
    wide.status = TrackingStatus::kLost;
  return wide;
}

void Detector::finish(const FrameView& frame, RefinedCandidate& candidate) {
  // Started as a guess, each point took the strongest edge in its range, and the frames after
  // followed the contrasts of those: beside a parallel edge or on textured clutter the run can
  // settle a few pixels off. Started again as a given pose, the contrasts are taken where this
  // pose puts the model's edges and the first solve is weighted at it, as a tracked frame is.
  // A confident run already fits within the edges' localisation and ends the search as it is.
  RefinedCandidate given = candidate;
  if (params_.given_iterations > 0 && candidate.status != TrackingStatus::kLost && !confident(candidate, params_) &&
      run_frames(tracker_, frame, params_.given_iterations, given, Tracker::StartPose::kGiven) &&
      better(given, candidate, params_))
    candidate = given;
  settle(frame, candidate);
}

RefinedCandidate Detector::refine_tilted(const FrameView& frame, const TemplateMatch& match, const Se3& start) {
  // A tilted start is a refined pose turned by a few degrees, no template's: the tracking range
  // reaches its edges, and neither the wider search nor a start as a given pose is run.
  RefinedCandidate candidate;
  candidate.match = match;
  candidate.camera_from_model = start;
  if (run_frames(tracker_, frame, params_.refine_iterations, candidate)) settle(frame, candidate);
  return candidate;
}

void Detector::settle(const FrameView& frame, RefinedCandidate& candidate) {
  // The narrow search settles the pose; the judgement stays the tracking range's, since a search
  // that narrow finds edges near any pose on a cluttered image.
  if (!acceptable(candidate, params_)) return;
  RefinedCandidate settled = candidate;
  if (run_frames(fine_, frame, params_.fine_iterations, settled) && settled.status == TrackingStatus::kTracked)
    candidate.camera_from_model = settled.camera_from_model;
}

void Detector::suppress_neighbours() {
  const real cos_half = cos(real(0.5) * params_.suppress_deg * real(kRadiansPerDegree));
  const real reach = params_.suppress_radii * templates_.extent.radius;
  std::vector<Se3> kept_poses;
  size_t kept = 0;
  for (const TemplateMatch& m : matches_) {
    const Se3 pose = pose_of_match(templates_, m, params_.spread);
    const Vec3 centre = pose * templates_.extent.centre;
    bool near = false;
    for (const Se3& other : kept_poses) {
      // cos(angle / 2) of the relative rotation is its quaternion's w: sqrt(1 + trace) / 2.
      const Mat33 relative = other.rotation().transpose() * pose.rotation();
      const real trace = relative.m[0][0] + relative.m[1][1] + relative.m[2][2];
      const real w2 = (real(1) + trace) / real(4);
      near = near || (w2 >= cos_half * cos_half && norm(other * templates_.extent.centre - centre) <= reach);
    }
    if (near) continue;
    kept_poses.push_back(pose);
    matches_[kept++] = m;
  }
  matches_.resize(kept);
}

std::vector<TemplateMatch> Detector::screen(const FrameView& frame) {
  if (matches_.size() <= 1) return matches_;
  std::vector<RefinedCandidate> screened;
  for (const TemplateMatch& m : matches_) {
    RefinedCandidate c;
    c.match = m;
    c.camera_from_model = pose_of_match(templates_, m, params_.spread);
    if (!run_frames(screen_, frame, params_.screen_iterations, c)) c.status = TrackingStatus::kLost;
    screened.push_back(c);
  }
  // Tracked before uncertain before lost (a screen that already fits is the likeliest to refine
  // to a confident fit), then the most control points kept (a pose too far away, whose smaller
  // image lines up with a part of the object's edges, keeps fewer). Stable: among equals the
  // better match first.
  std::stable_sort(screened.begin(), screened.end(), [](const RefinedCandidate& a, const RefinedCandidate& b) {
    if (a.status != b.status) return static_cast<int>(a.status) < static_cast<int>(b.status);
    return a.kept > b.kept;
  });
  std::vector<TemplateMatch> kept;
  const size_t count = std::min(screened.size(), static_cast<size_t>(params_.refined_candidates));
  for (size_t k = 0; k < count; ++k) kept.push_back(screened[k].match);
  return kept;
}

bool Detector::near_miss(const RefinedCandidate& c) const {
  return c.status == TrackingStatus::kTracked && c.support >= params_.min_support && !confident(c, params_);
}

const RefinedCandidate* Detector::restart_base(const Detection& detection) const {
  const RefinedCandidate* from = nullptr;
  for (const RefinedCandidate& c : detection.refined) {
    if (confident(c, params_)) return nullptr;
    if (c.status != TrackingStatus::kLost && c.support >= params_.min_support && (!from || better(c, *from, params_)))
      from = &c;
  }
  return from;
}

void Detector::restart_tilted(const FrameView& frame, Detection& detection, const RefinedCandidate& base) {
  if (!(params_.restart_tilt_deg > real(0))) return;
  const Vec3& centre_in_model = templates_.extent.centre;
  const Vec3 centre = base.camera_from_model * centre_in_model;
  const real t = params_.restart_tilt_deg * real(kRadiansPerDegree), o(0);
  const Vec3 tilts[4] = {Vec3{t, o, o}, Vec3{-t, o, o}, Vec3{o, t, o}, Vec3{o, -t, o}};
  for (const Vec3& tilt : tilts) {
    if (budget_spent()) return;
    // Turned about the camera's axis through the model's centre: the centre stays where it was.
    const Mat33 rotation = rotation_exp(tilt) * base.camera_from_model.rotation();
    detection.refined.push_back(refine_tilted(frame, base.match, Se3(rotation, centre - rotation * centre_in_model)));
    if (confident(detection.refined.back(), params_)) return;
  }
}

bool Detector::search_over(const Detection& detection) const {
  return budget_spent() || (!detection.refined.empty() && confident(detection.refined.back(), params_));
}

void Detector::search(const FrameView& frame, Detection& detection) {
  // Pass 1, the screened candidates best first: the tracking-range run, and the given start and
  // the settling when it ran. A candidate settling where an earlier one did stops there.
  std::vector<size_t> to_widen;
  bool restarted = false;
  size_t restarted_from = 0;  // index in detection.refined of the near miss restarted
  for (const TemplateMatch& m : screen(frame)) {
    RefinedCandidate c;
    c.match = m;
    c.camera_from_model = pose_of_match(templates_, m, params_.spread);
    const bool ran = run_frames(tracker_, frame, params_.refine_iterations, c);
    const bool repeated = ran && same_as_earlier(c, detection.refined);
    if (ran && !repeated) finish(frame, c);
    if (!ran) c.status = TrackingStatus::kLost;
    detection.refined.push_back(c);
    if (search_over(detection)) return;
    if (!repeated && !acceptable(c, params_)) to_widen.push_back(detection.refined.size() - 1);
    // The first near miss is the likeliest place of a confident fit: its tilted restarts come
    // before the other candidates' and the wider searches (DetectorParams::restart_tilt_deg).
    if (!restarted && near_miss(c)) {
      restarted = true;
      restarted_from = detection.refined.size() - 1;
      restart_tilted(frame, detection, c);
      if (search_over(detection)) return;
    }
  }
  // Pass 2: the wider search for the candidates whose tracking-range run was not acceptable, in
  // the same order; its result replaces the first when better.
  for (const size_t i : to_widen) {
    const TemplateMatch m = detection.refined[i].match;
    RefinedCandidate wide = refine_wide(frame, m, pose_of_match(templates_, m, params_.spread));
    if (better(wide, detection.refined[i], params_)) detection.refined[i] = wide;
    if (budget_spent() || confident(detection.refined[i], params_)) return;
  }
  // Still none confident: the best candidate's restarts, unless it is the near miss restarted.
  const RefinedCandidate* base = restart_base(detection);
  if (!base || (restarted && base == &detection.refined[restarted_from])) return;
  const RefinedCandidate from = *base;  // detection.refined grows below
  restart_tilted(frame, detection, from);
}

FrameView Detector::detection_frame() const {
  const bool reduced = detection_reduction(templates_.camera) > 1;
  return packed_frame(reduced ? reduced_.data() : grey_.data(), detecting_.width, detecting_.height, PixelLayout::kGrey8);
}

Result<RefinedCandidate> Detector::refine_from(const FrameView& frame, const Se3& start) {
  if (const std::optional<Error> refused = check_frame(frame, templates_.camera.width, templates_.camera.height))
    return *refused;
  match(frame);
  points_searched_ = 0;
  const FrameView grey = detection_frame();
  RefinedCandidate near = refine_near(grey, TemplateMatch{}, start);
  if (acceptable(near, params_)) return near;
  const RefinedCandidate wide = refine_wide(grey, TemplateMatch{}, start);
  return better(wide, near, params_) ? wide : near;
}

Result<Detection> Detector::detect(const FrameView& frame) {
  if (const std::optional<Error> refused = check_frame(frame, templates_.camera.width, templates_.camera.height))
    return *refused;
  Detection detection;
  points_searched_ = 0;
  frames_ = 0;
  match(frame);
  search(detection_frame(), detection);
  detection.points_searched = points_searched_;
  detection.frames = frames_;
  const RefinedCandidate* best = nullptr;
  for (const RefinedCandidate& c : detection.refined)
    if (!best || better(c, *best, params_)) best = &c;
  if (!best) return detection;
  detection.camera_from_model = best->camera_from_model;
  detection.score = best->kept_share;
  detection.match_share = best->match.share;
  detection.template_index = best->match.template_index;
  // Cut short, a later candidate might have fitted better: only a fit no other could better is
  // found (confident), never a merely acceptable pose that the rest of the search would have
  // replaced (a few degrees off, or a part of the object lined up with its edges).
  detection.cut_short = budget_spent() && !confident(*best, params_);
  detection.found = !detection.cut_short && acceptable(*best, params_);
  return detection;
}

}  // namespace edgetrack
