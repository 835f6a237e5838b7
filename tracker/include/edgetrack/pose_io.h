// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's .pos files: a pose vector tx ty tz (metres) and thetaU (radians), six numbers.
#pragma once

#include <string>

#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// Reads camera_from_model from a .pos file (six numbers separated by white space).
Result<Se3> read_pos(const std::string& path);
/// Writes camera_from_model as ViSP does: one number per line, tx ty tz tux tuy tuz.
/// Returns an Error when the file cannot be written.
Result<bool> write_pos(const std::string& path, const Se3& camera_from_model);

}  // namespace edgetrack
