// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's pose files: a pose vector tx ty tz (metres) and thetaU (radians), six numbers, or a
/// 4x4 homogeneous matrix.
#pragma once

#include <string>

#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The ranges a .pos file's values must lie in: translations within a kilometre, thetaU
/// components within two turns (4 pi rad; an angle needs at most pi).
constexpr double kMaxPosTranslation = 1000;
constexpr double kMaxPosRotation = 12.566370614359172;

/// How far a homogeneous matrix read from a file may be from one: R R^T from the identity, and
/// its last row from 0 0 0 1 (files hold float precision, 1e-7, or six printed digits).
constexpr double kPoseMatrixTolerance = 1e-5;

/// Reads camera_from_model from either of ViSP's pose files, told apart by how many numbers
/// they hold (white space separated, `#` comments): a .pos pose vector, six numbers tx ty tz
/// tux tuy tuz; or a 4x4 homogeneous matrix [R t; 0 0 0 1], sixteen numbers row by row, as
/// vpHomogeneousMatrix::save writes it. A value that is not a finite number inside its range,
/// an upper-left 3x3 that is not a rotation or a last row that is not 0 0 0 1 is refused with
/// its line; so is any other count of numbers.
Result<Se3> read_pos(const std::string& path);
/// Writes camera_from_model as ViSP does: one number per line, tx ty tz tux tuy tuz.
/// Returns an Error when the file cannot be written.
Result<bool> write_pos(const std::string& path, const Se3& camera_from_model);

}  // namespace edgetrack
