// SPDX-License-Identifier: BSD-3-Clause
/// The pinhole camera without distortion, ViSP's "perspective projection without distortion":
/// u = u0 + px * X / Z, v = v0 + py * Y / Z, pixel centres at integer (u, v).
#pragma once

#include "edgetrack/geometry.h"

namespace edgetrack {

struct PinholeCamera {
  real px{0};  ///< focal length in pixels, horizontally
  real py{0};  ///< focal length in pixels, vertically
  real u0{0};  ///< principal point, pixels
  real v0{0};
  int width = 0;  ///< image size in pixels
  int height = 0;

  /// The pixel a point in the camera frame projects to; the point must have Z > 0.
  Vec2 project(const Vec3& point_in_camera) const {
    return {u0 + px * point_in_camera.x / point_in_camera.z, v0 + py * point_in_camera.y / point_in_camera.z};
  }
  /// The point at depth Z (metres) seen at `pixel`.
  Vec3 unproject(const Vec2& pixel, const real& depth) const {
    return {(pixel.x - u0) / px * depth, (pixel.y - v0) / py * depth, depth};
  }
  /// The same camera for an image `factor` times larger (a supersampled render).
  PinholeCamera scaled(int factor) const;
};

}  // namespace edgetrack
