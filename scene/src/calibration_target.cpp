// SPDX-License-Identifier: BSD-3-Clause
/// The calibration target's layout and its ray-cast image.
#include "edgetrack/calibration_target.h"

#include <cmath>

namespace edgetrack {
namespace {

constexpr int kDark = 20, kWhite = 235, kOff = 128;

/// The circles' radius in spacings: a third for the symmetric grid (ViSP's grid2d), and for the
/// asymmetric grid's diagonal neighbours, sqrt(2) spacings apart, a little more.
real circle_radius(const CalibrationTarget& t) {
  return t.kind == TargetKind::kAsymmetricCircles ? real(0.4) : real(1) / real(3);
}

/// The pattern's extent in the target frame: from (x0, y0) to (x1, y1), border included.
void extent(const CalibrationTarget& t, real& x0, real& y0, real& x1, real& y1) {
  const real border = real(2) * t.spacing;
  const real last_x = t.kind == TargetKind::kAsymmetricCircles ? real(2 * t.columns - 1) * t.spacing
                                                                : real(t.columns - 1) * t.spacing;
  const real last_y = real(t.rows - 1) * t.spacing;
  x0 = -border, y0 = -border, x1 = last_x + border, y1 = last_y + border;
}

}  // namespace

std::vector<Vec3> CalibrationTarget::points() const {
  std::vector<Vec3> out;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int column = kind == TargetKind::kAsymmetricCircles ? 2 * i + j % 2 : i;
      out.push_back({real(column) * spacing, real(j) * spacing, real(0)});
    }
  return out;
}

bool CalibrationTarget::on_target(const real& x, const real& y) const {
  real x0, y0, x1, y1;
  extent(*this, x0, y0, x1, y1);
  return x >= x0 && x <= x1 && y >= y0 && y <= y1;
}

bool CalibrationTarget::dark(const real& x, const real& y) const {
  using std::floor;
  if (kind == TargetKind::kChessboard) {
    // Squares (columns + 1) x (rows + 1), the corner (0, 0) between the first four.
    const int a = static_cast<int>(floor(x / spacing)) + 1, b = static_cast<int>(floor(y / spacing)) + 1;
    if (a < 0 || a > columns || b < 0 || b > rows) return false;
    return (a + b) % 2 == 0;
  }
  // The nearest centre: its row, then its column in that row. In spacings, so that the squares
  // stay near 1: a fixed-point real squaring centimetres in metres keeps a few bits.
  const real radius = circle_radius(*this), u = x / spacing, w = y / spacing;
  const int j = static_cast<int>(floor(w + real(0.5)));
  for (int row = j - 1; row <= j + 1; ++row) {
    if (row < 0 || row >= rows) continue;
    const bool shifted = kind == TargetKind::kAsymmetricCircles;
    const real step = shifted ? real(2) : real(1);
    const real offset = shifted && row % 2 == 1 ? real(1) : real(0);
    const int i = static_cast<int>(floor((u - offset) / step + real(0.5)));
    if (i < 0 || i >= columns) continue;
    const real du = u - (offset + real(i) * step), dw = w - real(row);
    if (du * du + dw * dw <= radius * radius) return true;
  }
  return false;
}

TargetRenderer::TargetRenderer(const PinholeCamera& camera, int samples)
    : width_(camera.width), height_(camera.height), samples_(samples) {
  rays_.reserve(static_cast<size_t>(width_) * height_ * samples * samples);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      for (int s = 0; s < samples * samples; ++s) {
        const Vec2 pixel{real(x) + (real(s % samples) + real(0.5)) / real(samples) - real(0.5),
                         real(y) + (real(s / samples) + real(0.5)) / real(samples) - real(0.5)};
        rays_.push_back(camera.invert_distortion(camera.to_normalised(pixel)));
      }
}

std::vector<uint8_t> TargetRenderer::render(const CalibrationTarget& target, const Se3& camera_from_target) const {
  std::vector<uint8_t> image(static_cast<size_t>(width_) * height_, kOff);
  // The plane z = 0 of the target in the camera frame: through `origin`, normal `normal`.
  const Mat33& rotation = camera_from_target.rotation();
  const Vec3& origin = camera_from_target.translation();
  const Vec3 normal = rotation * Vec3{real(0), real(0), real(1)};
  const Mat33 target_from_camera = rotation.transpose();
  const real reach = dot(normal, origin);
  const int count = samples_ * samples_;
  for (size_t pixel = 0; pixel < image.size(); ++pixel) {
    int sum = 0;
    for (int s = 0; s < count; ++s) {
      const Vec2& n = rays_[pixel * count + s];
      const Vec3 ray{n.x, n.y, real(1)};
      const real facing = dot(normal, ray);
      const real depth = facing == real(0) ? real(-1) : reach / facing;
      if (depth <= real(0)) {
        sum += kOff;
        continue;
      }
      const Vec3 p = target_from_camera * (depth * ray - origin);
      sum += !target.on_target(p.x, p.y) ? kOff : target.dark(p.x, p.y) ? kDark : kWhite;
    }
    image[pixel] = static_cast<uint8_t>((sum + count / 2) / count);
  }
  return image;
}

}  // namespace edgetrack
