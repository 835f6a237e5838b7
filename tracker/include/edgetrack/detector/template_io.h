// SPDX-License-Identifier: BSD-3-Clause
/// Template files (`edgetrack templates`, docs/FORMATS.md): a text header with the format
/// version, the model's fingerprint, the camera and the parameters the templates were made
/// with, then one line per template. Reading checks the header against the model and the camera
/// in use, so a stale file is refused rather than matched.
#pragma once

#include <string>

#include "edgetrack/detector/template_set.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"

namespace edgetrack {

/// The format version this build writes and reads. Version 2 holds, for a camera above
/// kMaxDetectionSide, the templates made at its detection_camera(); version 1 files are read
/// when their camera is not above it (the same templates) and refused otherwise.
constexpr int kTemplateFormatVersion = 2;

/// Writes `set` to `path`; an Error names the file when it cannot be written.
Result<bool> write_templates(const std::string& path, const TemplateSet& set);

/// Reads the templates of `path`, refusing (with the file and the line) a file that is not a
/// template file, another format version, templates made for another model or camera, and any
/// value out of its range.
Result<TemplateSet> read_templates(const std::string& path, const EdgeModel& model, const PinholeCamera& camera);

/// Templates linked into a program as constant data: the C++ source `edgetrack templates --cxx`
/// writes (write_template_source) defines one, `edgetrack_constant_templates`, whose arrays a
/// firmware keeps in flash.
struct ConstantTemplates {
  const char* header;  ///< the template file's header, as write_templates writes it
  const Template* templates;
  size_t template_count;
  const TemplateFeature* features;
  size_t feature_count;
};

/// Writes `set` to `path` as a C++ source that defines `const edgetrack::ConstantTemplates
/// edgetrack_constant_templates`, its templates and features in constexpr arrays, with the
/// numbers of the template file; an Error names the file when it cannot be written.
Result<bool> write_template_source(const std::string& path, const TemplateSet& set);

/// The set of `constant`, its header checked as read_templates checks a file's against `model`
/// and `camera` (errors name `name`); its templates and features are read in place, not copied
/// (TemplateArray::read_in_place).
Result<TemplateSet> constant_template_set(const ConstantTemplates& constant, const EdgeModel& model,
                                          const PinholeCamera& camera, const std::string& name);

/// The camera as the file states it (and as the check compares it): px py u0 v0 to 6 decimals
/// and the image size.
std::string camera_description(const PinholeCamera& camera);

}  // namespace edgetrack
