// SPDX-License-Identifier: BSD-3-Clause
/// The options `detect` and `templates` share: the range the templates cover and where they come
/// from (made now, or read from a `--templates` file made by `edgetrack templates`).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "args.h"
#include "edgetrack/detector/auto_init_tracker.h"
#include "edgetrack/detector/template_set.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"

namespace edgetrack_app {

/// --distance, --cone, --axis, --subdivisions, --in-plane.
std::vector<OptionSpec> template_range_specs();

/// The template parameters those options give (the defaults for the absent ones).
edgetrack::Result<edgetrack::TemplateParams> template_params_from(const Args& args);

/// `--detector NAME=VALUE,...` of `detect` and `track`: the detector's settings over the
/// configuration's <edgetrack><detector> (edgetrack::set_detector_param).
OptionSpec detector_option_spec();
edgetrack::Result<edgetrack::DetectorParams> detector_params_from(const Args& args,
                                                                  const edgetrack::DetectorParams& configured);

/// `track --init-auto`'s tracker: the templates of `--templates FILE` (checked against the model
/// and the camera), else the default range with `--init-distance MIN:MAX`, made now.
edgetrack::Result<std::unique_ptr<edgetrack::AutoInitTracker>> auto_init_tracker(
    const Args& args, const edgetrack::EdgeModel& model, const edgetrack::PinholeCamera& camera,
    const edgetrack::TrackerParams& tracking, const edgetrack::DetectorParams& detection);

/// A line on stdout when the detector reduces frames of `camera`'s size (edgetrack::
/// detection_reduction), naming the size it detects at (`command`: the command's name).
void print_detection_reduction(const edgetrack::PinholeCamera& camera, const char* command);

/// The templates of `--templates FILE` when given (checked against the model and the camera),
/// else made now from the range options.
edgetrack::Result<edgetrack::TemplateSet> templates_for(const Args& args, const edgetrack::EdgeModel& model,
                                                        const edgetrack::PinholeCamera& camera);

}  // namespace edgetrack_app
