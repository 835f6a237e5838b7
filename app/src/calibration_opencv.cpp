// SPDX-License-Identifier: BSD-3-Clause
/// calibration.h through OpenCV's calib3d.
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdio>

#include "calibration.h"
#include "visp_lens_fit.h"

using edgetrack::Error;
using edgetrack::PinholeCamera;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

std::vector<cv::Point2f> to_cv(const std::vector<PixelPoint>& points) {
  std::vector<cv::Point2f> out;
  for (const PixelPoint& p : points) out.emplace_back(static_cast<float>(p.u), static_cast<float>(p.v));
  return out;
}

/// One calibrateCamera run with `flags`: the camera (lens coefficients left in `coefficients`)
/// and its errors.
CalibratedModel run_calibration(const std::vector<std::vector<cv::Point3f>>& object,
                                const std::vector<std::vector<cv::Point2f>>& image, int width, int height, int flags,
                                cv::Mat& coefficients) {
  cv::Mat k = cv::Mat::eye(3, 3, CV_64F), rvecs, tvecs, deviations_in, deviations_out, view_errors;
  coefficients = cv::Mat::zeros(5, 1, CV_64F);
  CalibratedModel model;
  model.rms_px = cv::calibrateCamera(object, image, cv::Size(width, height), k, coefficients, rvecs, tvecs,
                                     deviations_in, deviations_out, view_errors, flags);
  for (int i = 0; i < view_errors.rows; ++i) model.view_rms_px.push_back(view_errors.at<double>(i));
  model.camera = PinholeCamera(real(k.at<double>(0, 0)), real(k.at<double>(1, 1)), real(k.at<double>(0, 2)),
                               real(k.at<double>(1, 2)), width, height);
  return model;
}

/// The corners to a fraction of a pixel (cv::cornerSubPix), in a window that stays inside the
/// squares around each corner: a third of the shortest distance between neighbouring corners.
void refine_corners(const cv::Mat& image, const cv::Size& count, std::vector<cv::Point2f>& corners) {
  double shortest = 1e9;
  for (int j = 0; j < count.height; ++j)
    for (int i = 0; i < count.width; ++i) {
      const cv::Point2f& p = corners[static_cast<size_t>(j * count.width + i)];
      if (i + 1 < count.width) shortest = std::min(shortest, cv::norm(p - corners[static_cast<size_t>(j * count.width + i + 1)]));
      if (j + 1 < count.height) shortest = std::min(shortest, cv::norm(p - corners[static_cast<size_t>((j + 1) * count.width + i)]));
    }
  const int half = std::max(2, std::min(11, static_cast<int>(shortest / 3)));
  cv::cornerSubPix(image, corners, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4));
}

}  // namespace

std::vector<PixelPoint> find_target(const edgetrack::CalibrationTarget& target, const uint8_t* grey, int width,
                                    int height) {
  const cv::Mat image(height, width, CV_8UC1, const_cast<uint8_t*>(grey));
  const cv::Size count(target.columns, target.rows);
  std::vector<cv::Point2f> found;
  bool ok = false;
  switch (target.kind) {
    case edgetrack::TargetKind::kChessboard:
      // The sector-based detector finds boards the classic one misses (strong barrel, steep
      // views), but its corners lean towards the image centre (px 0.5 % short on rendered
      // boards); cornerSubPix's refinement is unbiased there.
      ok = cv::findChessboardCornersSB(image, count, found, cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_EXHAUSTIVE);
      if (ok) refine_corners(image, count, found);
      break;
    case edgetrack::TargetKind::kCircles:
      ok = cv::findCirclesGrid(image, count, found, cv::CALIB_CB_SYMMETRIC_GRID);
      break;
    case edgetrack::TargetKind::kAsymmetricCircles:
      ok = cv::findCirclesGrid(image, count, found, cv::CALIB_CB_ASYMMETRIC_GRID);
      break;
  }
  std::vector<PixelPoint> out;
  if (!ok || found.size() != static_cast<size_t>(target.columns) * target.rows) return out;
  for (const cv::Point2f& p : found) out.push_back({p.x, p.y});
  return out;
}

void draw_target_points(RgbImage& image, const edgetrack::CalibrationTarget& target,
                        const std::vector<PixelPoint>& points) {
  cv::Mat mat(image.height, image.width, CV_8UC3, image.rgb.data());
  cv::drawChessboardCorners(mat, cv::Size(target.columns, target.rows), to_cv(points), true);
}

Result<Calibration> calibrate_views(const edgetrack::CalibrationTarget& target,
                                    const std::vector<std::vector<PixelPoint>>& views, int width, int height,
                                    bool with_k3) {
  if (views.size() < 3) return Error{"", 0, "calibration needs the target in 3 frames or more"};
  std::vector<cv::Point3f> layout;
  for (const edgetrack::Vec3& p : target.points())
    layout.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y), 0.f);
  const std::vector<std::vector<cv::Point3f>> object(views.size(), layout);
  std::vector<std::vector<cv::Point2f>> image;
  for (const auto& view : views) image.push_back(to_cv(view));
  Calibration c;
  try {
    cv::Mat coefficients;
    c.opencv = run_calibration(object, image, width, height, with_k3 ? 0 : cv::CALIB_FIX_K3, coefficients);
    c.opencv.camera.lens.model = edgetrack::LensModel::kOpenCv;
    c.opencv.camera.lens.k1 = real(coefficients.at<double>(0));
    c.opencv.camera.lens.k2 = real(coefficients.at<double>(1));
    c.opencv.camera.lens.p1 = real(coefficients.at<double>(2));
    c.opencv.camera.lens.p2 = real(coefficients.at<double>(3));
    c.opencv.camera.lens.k3 = real(coefficients.at<double>(4));
    // OpenCV's model with k1 alone is ViSP's forward model, x_d = x (1 + kud r^2): calibrating
    // it fits ViSP's lens (with its own px, py, u0, v0) to the points themselves.
    const int radial_only = cv::CALIB_FIX_K2 | cv::CALIB_FIX_K3 | cv::CALIB_ZERO_TANGENT_DIST;
    c.visp = run_calibration(object, image, width, height, radial_only, coefficients);
    c.visp.camera.lens.model = edgetrack::LensModel::kVisp;
    c.visp.camera.lens.kud = real(coefficients.at<double>(0));
    c.visp.camera.lens.kdu = real(fitted_kdu(c.visp.camera));
    c.visp_pinhole = run_calibration(object, image, width, height, radial_only | cv::CALIB_FIX_K1, coefficients);
  } catch (const cv::Exception& e) {
    return Error{"", 0, std::string("OpenCV's calibration failed: ") + e.err};
  }
  return c;
}

Result<bool> write_opencv_calibration(const std::string& path, const CalibratedModel& model, int frames) {
  const PinholeCamera& c = model.camera;
  const cv::Mat k = (cv::Mat_<double>(3, 3) << static_cast<double>(c.px), 0, static_cast<double>(c.u0), 0,
                     static_cast<double>(c.py), static_cast<double>(c.v0), 0, 0, 1);
  const cv::Mat d = (cv::Mat_<double>(5, 1) << static_cast<double>(c.lens.k1), static_cast<double>(c.lens.k2),
                     static_cast<double>(c.lens.p1), static_cast<double>(c.lens.p2), static_cast<double>(c.lens.k3));
  // Opened once by us first: cv::FileStorage would log its own line about a path it cannot open.
  std::FILE* probe = std::fopen(path.c_str(), "w");
  if (!probe) return Error{path, 0, "cannot open the file for writing"};
  std::fclose(probe);
  try {
    // The format is named, not taken from the name's extension: the file is written as NAME.partial.
    cv::FileStorage file(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
    if (!file.isOpened()) return Error{path, 0, "cannot open the file for writing"};
    file << "nr_of_frames" << frames << "image_width" << c.width << "image_height" << c.height
         << "camera_matrix" << k << "distortion_coefficients" << d << "avg_reprojection_error" << model.rms_px;
    file.release();
  } catch (const cv::Exception& e) {
    return Error{path, 0, std::string("write failed: ") + e.err};
  }
  return true;
}

}  // namespace edgetrack_app
