// SPDX-License-Identifier: BSD-3-Clause
/// Camera calibrations as users have them, read without OpenCV or ViSP (so on the ARM target
/// too): ViSP's camera file as vpXmlParserCamera writes it, and OpenCV's calibration file
/// (cv::FileStorage YAML or XML with camera_matrix, distortion_coefficients, image_width and
/// image_height, as OpenCV's calibration sample writes it).
#pragma once

#include <string>

#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"

namespace edgetrack {

/// Which camera of a file to take. ViSP's files may hold several cameras: the one whose
/// <name> is `name` (any when empty) and whose image size is width x height (any when 0).
struct CameraChoice {
  std::string name;
  int width = 0;
  int height = 0;
};

/// The camera in the file at `path`, its format told by its content: an XML root <root> is
/// ViSP's (of the chosen camera, the perspectiveProjWithDistortion model when it has one,
/// else perspectiveProjWithoutDistortion), <opencv_storage> or a "%YAML" first line OpenCV's
/// (k1, k2, p1, p2[, k3]; 8, 12 or 14 coefficients whose rational, thin-prism and tilt terms
/// are 0 read as those five, and refused otherwise). Anything missing, malformed or outside
/// its range is an Error naming the file and the line.
Result<PinholeCamera> read_camera_file(const std::string& path, const CameraChoice& choice = CameraChoice{});

}  // namespace edgetrack
