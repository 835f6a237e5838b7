// SPDX-License-Identifier: BSD-3-Clause
/// Camera calibration from views of a planar target (host: OpenCV finds the target and
/// calibrates). One calibration gives the camera in the three models our calibration files hold:
/// OpenCV's (k1 k2 p1 p2, and k3 when asked), ViSP's perspectiveProjWithDistortion and ViSP's
/// perspectiveProjWithoutDistortion, each fitted to the target's points on its own.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/calibration_target.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "image_io.h"

namespace edgetrack_app {

/// A pixel position, in the grey image's pixel grid (centres at integers).
struct PixelPoint {
  double u = 0, v = 0;
};

/// The target's points found in a grey image (row-major, width x height), in
/// CalibrationTarget::points() order, to a fraction of a pixel; empty when the whole target is
/// not found.
std::vector<PixelPoint> find_target(const edgetrack::CalibrationTarget& target, const uint8_t* grey, int width,
                                    int height);

/// Draws the points found on `image` as OpenCV draws a found pattern (coloured rows joined).
void draw_target_points(RgbImage& image, const edgetrack::CalibrationTarget& target,
                        const std::vector<PixelPoint>& points);

/// One model's calibration: the camera and its RMS reprojection error over all points (pixels).
struct CalibratedModel {
  edgetrack::PinholeCamera camera;
  double rms_px = 0;
  std::vector<double> view_rms_px;  ///< per view, in the views' order
};

struct Calibration {
  CalibratedModel opencv;        ///< OpenCV's lens: k1 k2 p1 p2 (k3)
  CalibratedModel visp;          ///< ViSP's lens: kud (OpenCV's k1 alone), kdu fitted to it
  CalibratedModel visp_pinhole;  ///< no lens
};

/// Calibrates a camera of width x height from the target's points in each view (at least 3).
/// `with_k3`: OpenCV's model gets its sixth-order radial term too.
edgetrack::Result<Calibration> calibrate_views(const edgetrack::CalibrationTarget& target,
                                               const std::vector<std::vector<PixelPoint>>& views, int width,
                                               int height, bool with_k3);

/// Writes OpenCV's calibration file (cv::FileStorage YAML, as OpenCV's calibration sample:
/// image_width, image_height, camera_matrix, distortion_coefficients k1 k2 p1 p2 k3, and the
/// number of frames and RMS error) to `path`.
edgetrack::Result<bool> write_opencv_calibration(const std::string& path, const CalibratedModel& model, int frames);

}  // namespace edgetrack_app
