// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's .pos files: a pose vector tx ty tz (metres) and thetaU (radians), six numbers.
#pragma once

#include <string>

#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The ranges a .pos file's values must lie in: translations within a kilometre, thetaU
/// components within two turns (4 pi rad; an angle needs at most pi).
constexpr double kMaxPosTranslation = 1000;
constexpr double kMaxPosRotation = 12.566370614359172;

/// Reads camera_from_model from a .pos file (six numbers separated by white space, `#` comments);
/// a value that is not a finite number inside its range is refused with its line.
Result<Se3> read_pos(const std::string& path);
/// Writes camera_from_model as ViSP does: one number per line, tx ty tz tux tuy tuz.
/// Returns an Error when the file cannot be written.
Result<bool> write_pos(const std::string& path, const Se3& camera_from_model);

}  // namespace edgetrack
