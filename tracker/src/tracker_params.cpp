// SPDX-License-Identifier: BSD-3-Clause
/// The settings' limits and the sampling inputs derived from them.
#include "edgetrack/tracker_params.h"

#include <cmath>

#include "edgetrack/angles.h"
#include "edgetrack/number_text.h"
#include "edgetrack/rolling_shutter.h"

namespace edgetrack {
namespace {

/// "<ecm><range><tracking>" from "ecm/range/tracking".
std::string element_path(const std::string& field) {
  std::string path = "<";
  for (char c : field) path += c == '/' ? std::string("><") : std::string(1, c);
  return path + ">";
}

SettingProblem problem(const std::string& field, const std::string& limit, double value) {
  return {field, element_path(field) + " must be " + limit + ", not " + number_text(value)};
}

/// A setting no XML element holds, named in words.
SettingProblem unfiled(const std::string& name, const std::string& limit, double value) {
  return {"", name + " must be " + limit + ", not " + number_text(value)};
}

bool finite(const real& value) { return std::isfinite(static_cast<double>(value)); }

/// The first real setting that is not a finite number, by its name.
std::optional<SettingProblem> first_not_finite(const TrackerParams& p) {
  const struct {
    const char* field;  ///< the XML element, or empty
    const char* name;
    const real& value;
  } reals[] = {
      {"ecm/contrast/edge_threshold", "", p.me.threshold},
      {"ecm/contrast/mu1", "", p.me.mu1},
      {"ecm/contrast/mu2", "", p.me.mu2},
      {"ecm/sample/step", "", p.me.sample_step},
      {"face/angle_appear", "", p.faces.angle_appear},
      {"face/angle_disappear", "", p.faces.angle_disappear},
      {"face/near_clipping", "", p.faces.near_distance},
      {"face/far_clipping", "", p.faces.far_distance},
      {"lod/min_line_length_threshold", "", p.faces.min_line_length},
      {"lod/min_polygon_area_threshold", "", p.faces.min_polygon_area},
      {"", "the pose's x tolerance", p.pose.x_tolerance},
      {"", "the pose's f tolerance", p.pose.f_tolerance},
      {"", "the pose's g tolerance", p.pose.g_tolerance},
      {"", "the pose's rounds_settled_px", p.pose.rounds_settled_px},
      {"", "Tukey's c", p.pose.tukey_c},
      {"", "Tukey's floor", p.pose.tukey_floor},
      {"", "the motion's velocity share", p.motion.velocity_share},
      {"", "the motion's lost damping", p.motion.lost_damping},
      {"", "the motion's range per motion", p.motion.range_per_motion},
      {"", "the status' tracked scale", p.status.tracked_scale_px},
      {"", "the status' lost range share", p.status.lost_range_share},
      {"", "the status' lost scale floor", p.status.lost_scale_floor_px},
      {"", "the status' matched share", p.status.min_matched_share},
      {"", "the status' inlier share", p.status.min_inlier_share},
      {"", "the status' pose uncertainty bound", p.status.max_pose_uncertainty_px},
      {"", "the status' lost uncertainty share", p.status.lost_uncertainty_range_share},
      {"", "the status' edge location error", p.status.edge_location_px},
      {"edgetrack/camera/readout", "", p.readout},
  };
  for (const auto& r : reals) {
    if (finite(r.value)) continue;
    const std::string name = *r.field ? element_path(r.field) : std::string(r.name);
    return SettingProblem{r.field, name + " must be a finite number, not " + number_text(static_cast<double>(r.value))};
  }
  return std::nullopt;
}

}  // namespace

std::optional<SettingProblem> check_tracker_params(const TrackerParams& params) {
  if (auto not_finite = first_not_finite(params)) return not_finite;
  const MovingEdgeParams& me = params.me;
  // A mask needs a centre and neighbours; upstream's masks are at most one per degree.
  if (me.mask_size < 3 || me.mask_size > 15) return problem("ecm/mask/size", "3..15 pixels", me.mask_size);
  if (me.mask_number < 1 || me.mask_number > 180) return problem("ecm/mask/nb_mask", "1..180", me.mask_number);
  if (me.range < 1 || me.range > kMaxRange)
    return problem("ecm/range/tracking", "1.." + std::to_string(kMaxRange) + " pixels", me.range);
  if (!(me.threshold > real(0))) return problem("ecm/contrast/edge_threshold", "positive", static_cast<double>(me.threshold));
  if (me.mu1 < real(0) || me.mu1 > real(1)) return problem("ecm/contrast/mu1", "in [0, 1]", static_cast<double>(me.mu1));
  if (me.mu2 < real(0) || me.mu2 > real(1)) return problem("ecm/contrast/mu2", "in [0, 1]", static_cast<double>(me.mu2));
  if (me.sample_step < real(kMinSampleStep))
    return problem("ecm/sample/step", "at least " + number_text(kMinSampleStep) + " pixel",
                   static_cast<double>(me.sample_step));
  const FaceVisibilityParams& faces = params.faces;
  if (faces.angle_appear < real(0) || faces.angle_appear > real(kPi))
    return problem("face/angle_appear", "0..180 degrees", static_cast<double>(faces.angle_appear) * kDegreesPerRadian);
  if (faces.angle_disappear < real(0) || faces.angle_disappear > real(kPi))
    return problem("face/angle_disappear", "0..180 degrees", static_cast<double>(faces.angle_disappear) * kDegreesPerRadian);
  if (faces.near_clipping && faces.near_distance < real(0))
    return problem("face/near_clipping", "at least 0 metres", static_cast<double>(faces.near_distance));
  if (faces.far_clipping && !(faces.far_distance > real(0)))
    return problem("face/far_clipping", "positive (metres)", static_cast<double>(faces.far_distance));
  if (faces.near_clipping && faces.far_clipping && !(faces.far_distance > faces.near_distance))
    return problem("face/far_clipping",
                   "beyond near_clipping (" + number_text(static_cast<double>(faces.near_distance)) + " m)",
                   static_cast<double>(faces.far_distance));
  if (faces.min_line_length < real(0))
    return problem("lod/min_line_length_threshold", "at least 0 pixels", static_cast<double>(faces.min_line_length));
  if (faces.min_polygon_area < real(0))
    return problem("lod/min_polygon_area_threshold", "at least 0 square pixels",
                   static_cast<double>(faces.min_polygon_area));
  if (params.hypotheses < 1 || params.hypotheses > kMaxHypotheses)
    return unfiled("the number of edge hypotheses", "1 to " + std::to_string(kMaxHypotheses), params.hypotheses);
  if (params.border < 0 || params.border > static_cast<int>(kMaxRange))
    return unfiled("the image border", "0.." + std::to_string(kMaxRange) + " pixels", params.border);
  const PoseParams& pose = params.pose;
  if (pose.max_evaluations < 1 || pose.max_evaluations > 10000)
    return unfiled("the pose's evaluations", "1..10000", pose.max_evaluations);
  if (pose.robust_evaluations < 1 || pose.robust_evaluations > 10000)
    return unfiled("the pose's robust evaluations", "1..10000", pose.robust_evaluations);
  if (pose.robust_rounds < 0 || pose.robust_rounds > 100) return unfiled("the pose's robust rounds", "0..100", pose.robust_rounds);
  if (pose.min_points < 1) return unfiled("the pose's least points", "at least 1", pose.min_points);
  // MINPACK's tolerances are nonnegative: S47.16 rounds the default x_tolerance (1e-6) to 0.
  if (!(pose.x_tolerance >= real(0)) || !(pose.f_tolerance >= real(0)) || !(pose.g_tolerance >= real(0)))
    return SettingProblem{"", "the pose's tolerances must be at least 0"};
  if (pose.tukey_c < real(0) || pose.tukey_floor < real(0) || pose.rounds_settled_px < real(0))
    return SettingProblem{"", "Tukey's c and floor and the pose's rounds_settled_px must be at least 0"};
  const MotionParams& motion = params.motion;
  if (motion.velocity_share < real(0) || motion.velocity_share > real(1) || motion.lost_damping < real(0) ||
      motion.lost_damping > real(1))
    return SettingProblem{"", "the motion's velocity share and lost damping must be in [0, 1]"};
  if (motion.range_per_motion < real(0) || motion.range_per_motion > real(100))
    return unfiled("the motion's range per motion", "in [0, 100]", static_cast<double>(motion.range_per_motion));
  if (motion.max_range_factor < 1 || motion.max_range_factor > 16)
    return unfiled("the motion's largest range factor", "1..16", motion.max_range_factor);
  if (motion.recovery_frames < 0 || motion.start_frames < 0)
    return SettingProblem{"", "the motion's recovery and start frames must be at least 0"};
  if (params.readout < real(-kMaxReadout) || params.readout > real(kMaxReadout))
    return problem("edgetrack/camera/readout", "-1..1 frame intervals", static_cast<double>(params.readout));
  const std::string status = check_status_params(params.status);
  if (!status.empty()) return SettingProblem{"", status};
  const ThinLineParams& lines = params.thin_lines;
  if (lines.dark_px < 1 || lines.dark_px > 8 || lines.beyond_px < 1 || lines.beyond_px > 8)
    return SettingProblem{"", "the thin-line test's dark_px and beyond_px must be 1 to 8 pixels"};
  if (!(lines.return_share > real(0) && lines.return_share <= real(1)))
    return SettingProblem{"", "the thin-line test's return_share must be above 0 and at most 1"};
  if (static_cast<int>(lines.check) < 0 || static_cast<int>(lines.check) > 2 ||
      !(lines.check_sigmas > real(0) && lines.check_sigmas <= real(100)))
    return SettingProblem{"", "the drift check must be 0, 1 or 2 and its check_sigmas above 0 and at most 100"};
  return std::nullopt;
}


SamplingParams sampling_params(const TrackerParams& params) {
  SamplingParams sampling;
  sampling.step = params.me.sample_step;
  sampling.border = params.border;
  sampling.clipping = view_clipping(params.faces);
  return sampling;
}

}  // namespace edgetrack
