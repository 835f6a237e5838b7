// SPDX-License-Identifier: BSD-3-Clause
/// A planar camera-calibration target: a chessboard or a grid of circles (symmetric or
/// asymmetric, OpenCV's layouts), its feature points in its own frame, and an exact ray-cast
/// image of it through a camera and its lens. `edgetrack calibrate` takes its points from here;
/// the tests render it through a known camera and check what calibrate recovers.
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

enum class TargetKind : uint8_t {
  kChessboard,         ///< columns x rows inner corners, `spacing` the side of a square
  kCircles,            ///< columns x rows circles, `spacing` between neighbouring centres
  kAsymmetricCircles,  ///< OpenCV's asymmetric grid: row j shifted by `spacing` when j is odd,
                       ///< centres 2 `spacing` apart along a row, rows `spacing` apart
};

struct CalibrationTarget {
  TargetKind kind = TargetKind::kChessboard;
  int columns = 9;  ///< features along a row (x)
  int rows = 6;     ///< features along a column (y)
  real spacing{0.02};  ///< metres

  /// The features in the target frame (z = 0), row by row, in the order OpenCV's detectors
  /// return them: corner or centre (i, j) at (i s, j s), or ((2 i + j % 2) s, j s) for the
  /// asymmetric grid.
  std::vector<Vec3> points() const;
  /// Whether the target's point (x, y) (target frame, metres) is dark: a black square or a disc.
  /// Around the pattern the target is white for a border of two spacings, then ends.
  bool dark(const real& x, const real& y) const;
  /// Whether (x, y) lies on the target (the pattern and its white border).
  bool on_target(const real& x, const real& y) const;
};

/// Grey images (row-major, width x height of the camera) of calibration targets seen through a
/// camera and its lens: each of samples x samples samples of a pixel is the ray the lens's exact
/// inverse gives (worked out once, for every view), met with the target's plane: dark 20, white
/// 235, off the target 128; the samples averaged.
class TargetRenderer {
 public:
  TargetRenderer(const PinholeCamera& camera, int samples);
  std::vector<uint8_t> render(const CalibrationTarget& target, const Se3& camera_from_target) const;

 private:
  int width_, height_, samples_;
  std::vector<Vec2> rays_;  ///< normalised (x, y) of each sample, pixel by pixel, row by row
};

}  // namespace edgetrack
