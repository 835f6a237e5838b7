// SPDX-License-Identifier: BSD-3-Clause
/// The settings' limits and the sampling inputs derived from them.
#include "edgetrack/tracker_params.h"

#include <cmath>
#include <sstream>

namespace edgetrack {
namespace {

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

/// "<ecm><range><tracking>" from "ecm/range/tracking".
std::string element_path(const std::string& field) {
  std::string path = "<";
  for (char c : field) path += c == '/' ? std::string("><") : std::string(1, c);
  return path + ">";
}

SettingProblem problem(const std::string& field, const std::string& limit, double value) {
  return {field, element_path(field) + " must be " + limit + ", not " + number(value)};
}

}  // namespace

std::optional<SettingProblem> check_masks(unsigned int size, unsigned int number) {
  // A mask needs a centre and neighbours; upstream's masks are at most one per degree.
  if (size < 3 || size > 15) return problem("ecm/mask/size", "3..15 pixels", size);
  if (number < 1 || number > 180) return problem("ecm/mask/nb_mask", "1..180", number);
  return std::nullopt;
}

std::optional<SettingProblem> check_tracker_params(const TrackerParams& params) {
  const vpMe& me = params.me;
  if (auto masks = check_masks(me.getMaskSize(), me.getMaskNumber())) return masks;
  if (me.getRange() < 1) return problem("ecm/range/tracking", "at least 1 pixel", me.getRange());
  if (!(me.getThreshold() > real(0)))
    return problem("ecm/contrast/edge_threshold", "positive", static_cast<double>(me.getThreshold()));
  if (me.getMu1() < real(0) || me.getMu1() > real(1))
    return problem("ecm/contrast/mu1", "in [0, 1]", static_cast<double>(me.getMu1()));
  if (me.getMu2() < real(0) || me.getMu2() > real(1))
    return problem("ecm/contrast/mu2", "in [0, 1]", static_cast<double>(me.getMu2()));
  if (!(me.getSampleStep() > real(0)))
    return problem("ecm/sample/step", "positive", static_cast<double>(me.getSampleStep()));
  const FaceVisibilityParams& faces = params.faces;
  const double degrees = 180 / 3.14159265358979323846;
  if (faces.angle_appear < real(0) || faces.angle_appear > real(3.14159265358979323846))
    return problem("face/angle_appear", "0..180 degrees", static_cast<double>(faces.angle_appear) * degrees);
  if (faces.angle_disappear < real(0) || faces.angle_disappear > real(3.14159265358979323846))
    return problem("face/angle_disappear", "0..180 degrees", static_cast<double>(faces.angle_disappear) * degrees);
  if (faces.near_clipping && faces.near_distance < real(0))
    return problem("face/near_clipping", "at least 0 metres", static_cast<double>(faces.near_distance));
  if (faces.far_clipping && !(faces.far_distance > real(0)))
    return problem("face/far_clipping", "positive (metres)", static_cast<double>(faces.far_distance));
  if (faces.near_clipping && faces.far_clipping && !(faces.far_distance > faces.near_distance))
    return problem("face/far_clipping", "beyond near_clipping (" + number(static_cast<double>(faces.near_distance)) + " m)",
                   static_cast<double>(faces.far_distance));
  if (faces.min_line_length < real(0))
    return problem("lod/min_line_length_threshold", "at least 0 pixels", static_cast<double>(faces.min_line_length));
  if (faces.min_polygon_area < real(0))
    return problem("lod/min_polygon_area_threshold", "at least 0 square pixels",
                   static_cast<double>(faces.min_polygon_area));
  if (params.hypotheses < 1 || params.hypotheses > kMaxHypotheses)
    return SettingProblem{"", "the number of edge hypotheses must be 1 to " + std::to_string(kMaxHypotheses) + ", not " +
                                  number(params.hypotheses)};
  if (params.border < 0) return SettingProblem{"", "the image border must be at least 0 pixels, not " + number(params.border)};
  const std::string status = check_status_params(params.status);
  if (!status.empty()) return SettingProblem{"", status};
  return std::nullopt;
}

SamplingParams sampling_params(const TrackerParams& params) {
  SamplingParams sampling;
  sampling.step = params.me.getSampleStep();
  sampling.border = params.border;
  sampling.clipping = view_clipping(params.faces);
  return sampling;
}

}  // namespace edgetrack
