// SPDX-License-Identifier: BSD-3-Clause
/// The camera: ViSP's "perspective projection without distortion", u = u0 + px * X / Z,
/// v = v0 + py * Y / Z, pixel centres at integer (u, v), optionally through a lens distortion
/// (ViSP's "perspective projection with distortion", or OpenCV's radial-tangential model) of
/// the normalised coordinates (x, y) = (X / Z, Y / Z).
#pragma once

#include <cstdint>

#include "edgetrack/geometry.h"

namespace edgetrack {

/// Which distortion the lens applies to the normalised coordinates.
enum class LensModel : uint8_t {
  kNone,    ///< a pinhole
  kVisp,    ///< ViSP: x_d = x (1 + kud r^2); back with kdu: x = x_d (1 + kdu r_d^2)
  kOpenCv,  ///< OpenCV: x_d = x (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x y + p2 (r^2 + 2 x^2), y_d alike
};

/// The lens's coefficients, on normalised coordinates: a camera scaled or downscaled keeps them.
struct LensDistortion {
  LensModel model = LensModel::kNone;
  real kud{0};  ///< ViSP: undistorted to distorted (vpMeterPixelConversion)
  real kdu{0};  ///< ViSP: distorted to undistorted (vpPixelMeterConversion)
  real k1{0}, k2{0}, p1{0}, p2{0}, k3{0};  ///< OpenCV (rational and thin-prism terms are not modelled)
};

/// The derivative of the distorted normalised coordinates with respect to the undistorted ones.
struct LensJacobian {
  real xx{1}, xy{0}, yx{0}, yy{1};  ///< d x_d / d x, d x_d / d y, d y_d / d x, d y_d / d y
};

struct PinholeCamera {
  PinholeCamera() = default;
  PinholeCamera(const real& px, const real& py, const real& u0, const real& v0, int width, int height,
                const LensDistortion& lens = LensDistortion{})
      : px(px), py(py), u0(u0), v0(v0), width(width), height(height), lens(lens) {}

  real px{0};  ///< focal length in pixels, horizontally
  real py{0};  ///< focal length in pixels, vertically
  real u0{0};  ///< principal point, pixels
  real v0{0};
  int width = 0;  ///< image size in pixels
  int height = 0;
  LensDistortion lens;  ///< none by default

  /// Whether the lens bends anything: a model whose coefficients are all 0 is the pinhole,
  /// computed as before (bit for bit).
  bool distorted() const {
    const real zero(0);
    switch (lens.model) {
      case LensModel::kVisp: return !(lens.kud == zero && lens.kdu == zero);
      case LensModel::kOpenCv:
        return !(lens.k1 == zero && lens.k2 == zero && lens.p1 == zero && lens.p2 == zero && lens.k3 == zero);
      default: return false;
    }
  }

  /// The pixel a point in the camera frame projects to, through the lens; the point must have Z > 0.
  Vec2 project(const Vec3& point_in_camera) const {
    if (!distorted()) return project_without_lens(point_in_camera);
    return project_through_lens(point_in_camera);
  }
  /// project() of a camera that is not distorted(), for a loop that asked once.
  Vec2 project_without_lens(const Vec3& point_in_camera) const {
    return {u0 + px * point_in_camera.x / point_in_camera.z, v0 + py * point_in_camera.y / point_in_camera.z};
  }
  /// project() through the lens, out of line: the pinhole's stays short where it is inlined.
  Vec2 project_through_lens(const Vec3& point_in_camera) const;
  /// The point at depth Z (metres) seen at `pixel` (ViSP's model undistorts with kdu, as
  /// vpPixelMeterConversion does; OpenCV's is inverted by iteration, as cv::undistortPoints does).
  Vec3 unproject(const Vec2& pixel, const real& depth) const {
    if (!distorted()) return {(pixel.x - u0) / px * depth, (pixel.y - v0) / py * depth, depth};
    const Vec2 n = undistort(to_normalised(pixel));
    return {n.x * depth, n.y * depth, depth};
  }

  /// Normalised coordinates through the lens (ViSP's model inline: every sample, polyline
  /// point and pose-step match goes through it), and the lens's derivative there.
  Vec2 distort(const Vec2& n) const {
    if (lens.model != LensModel::kVisp) return distort_other(n);
    const real factor = real(1) + lens.kud * (n.x * n.x + n.y * n.y);
    return {n.x * factor, n.y * factor};
  }
  LensJacobian lens_jacobian(const Vec2& normalised) const;
  /// The row vector `covector` times the lens's derivative at `normalised`, (a, b) J_lens: the
  /// chain rule of a distance across an edge. ViSP's model, x (1 + kud r^2), gives
  /// (1 + kud r^2) (a, b) + 2 kud (a x + b y) (x, y) without the whole matrix.
  Vec2 lens_covector(const Vec2& normalised, const Vec2& covector) const;
  /// Both at once (the pose step's residuals and Jacobian, every match of every evaluation):
  /// ViSP's model inline, sharing r^2 and its factor.
  Vec2 distort(const Vec2& n, LensJacobian& j) const {
    if (lens.model != LensModel::kVisp) {
      j = lens_jacobian(n);
      return distort(n);
    }
    const real r2 = n.x * n.x + n.y * n.y;
    const real factor = real(1) + lens.kud * r2;
    const real twice_k = real(2) * lens.kud;
    const real kx = twice_k * n.x;
    j.xx = factor + kx * n.x;
    j.yy = factor + twice_k * n.y * n.y;
    j.xy = kx * n.y;
    j.yx = j.xy;
    return {n.x * factor, n.y * factor};
  }
  /// Distorted normalised coordinates back through the lens: with kdu for ViSP's model, by
  /// inverting the forward model for OpenCV's.
  Vec2 undistort(const Vec2& distorted_normalised) const;
  /// distort() for the models other than ViSP's.
  Vec2 distort_other(const Vec2& normalised) const;
  /// The exact inverse of distort() (Newton's method on the forward model), whatever the
  /// model: where a render must land on the pixels project() gives.
  Vec2 invert_distortion(const Vec2& distorted_normalised) const;

  Vec2 to_pixel(const Vec2& normalised) const { return {u0 + px * normalised.x, v0 + py * normalised.y}; }
  Vec2 to_normalised(const Vec2& pixel) const { return {(pixel.x - u0) / px, (pixel.y - v0) / py}; }
  /// A direction `along` at the pinhole pixel `pinhole`, as the lens turns and stretches it.
  Vec2 distort_direction(const Vec2& pinhole, const Vec2& along) const;

  /// How many pieces of equal parameter the image of the straight normalised segment a-b is cut
  /// into so that each piece's curve stays within `tolerance` pixels of its chord, at most `most`
  /// (1 for a pinhole). The bend s, how far the lens puts the image of the middle off the chord
  /// of the ends' images, leaves s / n^2 over each of n pieces: the curve is a parabola across
  /// the chord (ViSP's model: the distance d of the line from the centre gives an offset
  /// d (1 + k r^2), quadratic along it), and a parabola's sagitta falls with its chord squared.
  int chord_pieces(const Vec2& a, const Vec2& b, const real& tolerance, int most) const;
  /// Whether ViSP's radial model surely bends the image of segment a-b by no more than
  /// `tolerance` pixels, from a bound that needs no point through the lens: chord_pieces's
  /// shortcut to one piece, where Edge-ID's many short sides end.
  bool bend_within(const Vec2& a, const Vec2& b, const real& tolerance) const;

  /// The same camera without its lens.
  PinholeCamera pinhole() const { return {px, py, u0, v0, width, height}; }
  /// The same camera for an image `factor` times larger (a supersampled render).
  PinholeCamera scaled(int factor) const;
};

}  // namespace edgetrack
