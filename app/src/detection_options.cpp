// SPDX-License-Identifier: BSD-3-Clause
/// The template options of `detect` and `templates`.
#include "detection_options.h"

#include <cmath>
#include <cstdio>

#include "edgetrack/angles.h"
#include "edgetrack/detector/template_io.h"

using edgetrack::Error;
using edgetrack::Result;
using edgetrack::TemplateParams;

namespace edgetrack_app {

namespace {

/// "MIN:MAX" in metres, 0 < MIN < MAX <= 100, the value of `option`.
Result<bool> distance_range(const std::string& option, const std::string& text, TemplateParams& params) {
  double low = 0, high = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%lf:%lf%c", &low, &high, &end) != 2 || !std::isfinite(low) || !std::isfinite(high) ||
      !(low > 0) || !(high > low) || high > 100)
    return Error{"", 0, option + " '" + text + "': expected MIN:MAX in metres, 0 < MIN < MAX <= 100"};
  params.views.distance_min = real(low);
  params.views.distance_max = real(high);
  // A fixed-point real rounds a tiny MIN to 0, which would mean "the default range".
  if (!(params.views.distance_min > real(0)) || !(params.views.distance_max > params.views.distance_min))
    return Error{"", 0,
                 option + " '" + text + "': MIN and MAX round to " +
                     std::to_string(static_cast<double>(params.views.distance_min)) + " and " +
                     std::to_string(static_cast<double>(params.views.distance_max)) + " m in this build's real"};
  return true;
}

Result<bool> view_axis(const std::string& text, TemplateParams& params) {
  double x = 0, y = 0, z = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &x, &y, &z, &end) != 3 || !std::isfinite(x) || !std::isfinite(y) ||
      !std::isfinite(z) || std::sqrt(x * x + y * y + z * z) < 1e-6 || std::fabs(x) > 1e3 || std::fabs(y) > 1e3 ||
      std::fabs(z) > 1e3)
    return Error{"", 0, "--axis '" + text + "': expected X,Y,Z, a direction in the model frame (not zero)"};
  params.views.axis = {real(x), real(y), real(z)};
  return true;
}

}  // namespace

std::vector<OptionSpec> template_range_specs() {
  const edgetrack::ViewRange views;
  return {
      {"--distance", "MIN:MAX", "camera distances to the model's centre, metres (default: from the camera and the "
                                "model's size)", ""},
      {"--axis", "X,Y,Z", "the direction (model frame) the view cone is about, from the model towards the camera",
       "0,0,1"},
      {"--cone", "DEGREES", "half-angle of the view cone (180: the whole sphere)", "180"},
      {"--subdivisions", "N", "icosahedron subdivisions for the view directions, 0-4 (2: 162 directions)",
       std::to_string(views.subdivisions)},
      {"--in-plane", "N", "rotations about the optical axis per direction", std::to_string(views.in_plane_steps)},
  };
}

Result<TemplateParams> template_params_from(const Args& args) {
  TemplateParams params;
  if (args.has("--distance")) {
    auto range = distance_range("--distance", args.text("--distance"), params);
    if (!range.ok()) return range.error();
  }
  if (args.has("--axis")) {
    auto axis = view_axis(args.text("--axis"), params);
    if (!axis.ok()) return axis.error();
  }
  auto cone = args.number("--cone");
  if (!cone.ok()) return cone.error();
  if (cone.value() <= 0 || cone.value() > 180) return Error{"", 0, "--cone must be over 0 and at most 180 degrees"};
  params.views.max_angle = real(cone.value() * edgetrack::kPi / 180);
  auto subdivisions = args.integer("--subdivisions");
  if (!subdivisions.ok()) return subdivisions.error();
  params.views.subdivisions = subdivisions.value();
  auto in_plane = args.integer("--in-plane");
  if (!in_plane.ok()) return in_plane.error();
  params.views.in_plane_steps = in_plane.value();
  auto checked = edgetrack::check_template_params(params);
  if (!checked.ok()) return checked.error();
  return params;
}

OptionSpec detector_option_spec() {
  return {"--detector", "NAME=VALUE[,NAME=VALUE...]",
          "the detector's settings over the configuration's, named as in its <edgetrack><detector> block: "
          "max_points_searched, the work budget of one detection (control points on a QVGA frame, scaled by "
          "the frame's pixels; 0: none; docs/APP.md)",
          ""};
}

Result<edgetrack::DetectorParams> detector_params_from(const Args& args, const edgetrack::DetectorParams& configured) {
  edgetrack::DetectorParams params = configured;
  auto applied = apply_named_settings("--detector", args.text("--detector"), [&params](const std::string& name, double value) {
    return edgetrack::set_detector_param(params, name, value);
  });
  if (!applied.ok()) return applied.error();
  return params;
}

Result<std::unique_ptr<edgetrack::AutoInitTracker>> auto_init_tracker(const Args& args,
                                                                      const edgetrack::EdgeModel& model,
                                                                      const edgetrack::PinholeCamera& camera,
                                                                      const edgetrack::TrackerParams& tracking,
                                                                      const edgetrack::DetectorParams& detection) {
  Result<edgetrack::TemplateSet> templates = Error{};
  if (args.has("--templates")) {
    if (args.has("--init-distance"))
      return Error{"", 0, "--init-distance cannot be used with --templates: the file fixes the range"};
    templates = edgetrack::read_templates(args.text("--templates"), model, camera);
  } else {
    TemplateParams params;
    if (args.has("--init-distance")) {
      auto range = distance_range("--init-distance", args.text("--init-distance"), params);
      if (!range.ok()) return range.error();
    } else {
      params.views = edgetrack::auto_init_views(camera, edgetrack::model_extent(model));
    }
    templates = edgetrack::make_template_set(model, camera, params);
  }
  if (!templates.ok()) return templates.error();
  auto made = edgetrack::AutoInitTracker::create(model, camera, std::move(templates).value(),
                                                 detection, tracking);
  if (!made.ok()) return made.error();
  return std::unique_ptr<edgetrack::AutoInitTracker>(new edgetrack::AutoInitTracker(std::move(made).value()));
}

void print_detection_reduction(const edgetrack::PinholeCamera& camera, const char* command) {
  const int factor = edgetrack::detection_reduction(camera);
  if (factor == 1) return;
  const edgetrack::PinholeCamera reduced = edgetrack::detection_camera(camera);
  std::printf("%s: the image's shorter side is above the detector's %d px: detecting at 1/%d size (%dx%d), the pose "
              "is the full-size camera's\n",
              command, edgetrack::kMaxDetectionSide, factor, reduced.width, reduced.height);
}

Result<edgetrack::TemplateSet> templates_for(const Args& args, const edgetrack::EdgeModel& model,
                                             const edgetrack::PinholeCamera& camera) {
  if (args.has("--templates")) {
    for (const OptionSpec& spec : template_range_specs())
      if (args.has(spec.name))
        return Error{"", 0, std::string(spec.name) + " cannot be used with --templates: the file fixes the range"};
    return edgetrack::read_templates(args.text("--templates"), model, camera);
  }
  auto params = template_params_from(args);
  if (!params.ok()) return params.error();
  return edgetrack::make_template_set(model, camera, params.value());
}

}  // namespace edgetrack_app
