// SPDX-License-Identifier: BSD-3-Clause
/// The camera, model and start-pose limits of Tracker::create.
#include "edgetrack/tracker_inputs.h"

#include <cmath>

#include "edgetrack/number_text.h"
#include "edgetrack/pose_io.h"

namespace edgetrack {
namespace {

bool finite_within(const real& value, double bound) {
  const double v = static_cast<double>(value);
  return std::isfinite(v) && std::fabs(v) <= bound;
}

bool finite_within(const Vec3& p, double bound) {
  return finite_within(p.x, bound) && finite_within(p.y, bound) && finite_within(p.z, bound);
}

}  // namespace

std::optional<Error> check_intrinsics(const PinholeCamera& camera) {
  const auto refuse = [](const std::string& message) { return Error{"", 0, "the camera's " + message}; };
  const struct {
    const char* name;
    const real& value;
  } focal[2] = {{"px", camera.px}, {"py", camera.py}};
  for (const auto& f : focal) {
    const double v = static_cast<double>(f.value);
    if (!(std::isfinite(v) && v > 0 && v <= kMaxFocalPx))
      return refuse(std::string(f.name) + " must be in (0, " + number_text(kMaxFocalPx) + "] pixels, not " +
                    number_text(v));
  }
  const struct {
    const char* name;
    const real& value;
  } centre[2] = {{"u0", camera.u0}, {"v0", camera.v0}};
  for (const auto& c : centre) {
    if (!finite_within(c.value, kMaxPrincipalPointPx))
      return refuse(std::string(c.name) + " must be within +-" + number_text(kMaxPrincipalPointPx) + " pixels, not " +
                    number_text(static_cast<double>(c.value)));
  }
  const LensDistortion& lens = camera.lens;
  if (lens.model != LensModel::kNone && lens.model != LensModel::kVisp && lens.model != LensModel::kOpenCv)
    return refuse("lens model is none of LensModel's");
  const struct {
    const char* name;
    const real& value;
  } coefficients[7] = {{"kud", lens.kud}, {"kdu", lens.kdu}, {"k1", lens.k1}, {"k2", lens.k2},
                       {"p1", lens.p1},   {"p2", lens.p2},   {"k3", lens.k3}};
  for (const auto& c : coefficients) {
    if (!finite_within(c.value, kMaxLensCoefficient))
      return refuse(std::string("lens coefficient ") + c.name + " must be within +-" +
                    number_text(kMaxLensCoefficient) + ", not " + number_text(static_cast<double>(c.value)));
  }
  return std::nullopt;
}

std::optional<Error> check_camera(const PinholeCamera& camera) {
  if (auto problem = check_intrinsics(camera)) return problem;
  const auto refuse = [](const std::string& message) { return Error{"", 0, "the camera's " + message}; };
  if (camera.width == 0 && camera.height == 0) return std::nullopt;  // the first frame's size
  if (camera.width <= 0 || camera.height <= 0)
    return refuse("image size " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                  " is not a size (0x0: the first frame's)");
  if (camera.width > kMaxImageSide || camera.height > kMaxImageSide ||
      static_cast<long long>(camera.width) * camera.height > kMaxImagePixels)
    return refuse("image " + std::to_string(camera.width) + "x" + std::to_string(camera.height) + " is larger than " +
                  std::to_string(kMaxImageSide) + " pixels a side or " + std::to_string(kMaxImagePixels >> 20) +
                  " M pixels");
  return std::nullopt;
}

std::optional<Error> check_tracked_model(const EdgeModel& model) {
  if (primitive_count(model) == 0) return Error{"", 0, "the model has no edge, cylinder or circle to track"};
  if (primitive_count(model) > kMaxEdges) return Error{"", 0, "the model has too many primitives for Edge-ID"};
  bool inside = true;
  for (const Vec3& v : model.vertices) inside = inside && finite_within(v, kMaxModelCoordinate);
  for (const Cylinder& c : model.cylinders)
    inside = inside && finite_within(c.axis_a, kMaxModelCoordinate) && finite_within(c.axis_b, kMaxModelCoordinate) &&
             finite_within(c.radius, kMaxModelCoordinate);
  for (const Circle& c : model.circles) {
    inside = inside && finite_within(c.centre, kMaxModelCoordinate) && finite_within(c.radius, kMaxModelCoordinate);
    for (const Vec3& p : c.rim) inside = inside && finite_within(p, kMaxModelCoordinate);
  }
  for (const SurfaceTriangle& t : model.cylinder_surface)
    for (const Vec3& p : t.corners) inside = inside && finite_within(p, kMaxModelCoordinate);
  if (!inside)
    return Error{
        "", 0, "the model has a point that is not a finite number within +-" + number_text(kMaxModelCoordinate) + " m"};
  return std::nullopt;
}

std::optional<std::string> check_start_pose(const Se3& camera_from_model) {
  const Mat33& r = camera_from_model.rotation();
  for (const auto& row : r.m)
    for (const real& entry : row)
      if (!finite_within(entry, 1)) return std::string("has a rotation entry that is not a finite number in [-1, 1]");
  if (!finite_within(camera_from_model.translation(), kMaxPosTranslation))
    return "has a translation that is not a finite number within +-" + number_text(kMaxPosTranslation) + " m";
  // R R^T = I within what a rotation read from 6 decimals (or built in fixed point) keeps.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += static_cast<double>(r.m[i][k]) * static_cast<double>(r.m[j][k]);
      if (std::fabs(dot - (i == j ? 1 : 0)) > 1e-3) return std::string("has a rotation that is not orthonormal");
    }
  if (camera_from_model.translation().z <= real(0)) return std::string("puts the model behind the camera");
  return std::nullopt;
}

}  // namespace edgetrack
