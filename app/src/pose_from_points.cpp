// SPDX-License-Identifier: BSD-3-Clause
/// Pose from 2D-3D point correspondences: POSIT, then LM on the reprojection error.
#include "pose_from_points.h"

#include <array>
#include <cmath>
#include <cstdlib>

#include "edgetrack/number_text.h"
#include "vnl/algo/vnl_levenberg_marquardt.h"
#include "vnl/vnl_least_squares_function.h"

using edgetrack::Error;
using edgetrack::Mat33;
using edgetrack::PinholeCamera;
using edgetrack::Result;
using edgetrack::Se3;
using edgetrack::Vec2;
using edgetrack::Vec3;

namespace edgetrack_app {
namespace {

/// The numbers of a text file with # comments removed.
/// The numbers of a points file, each checked against `range`, with their lines.
Result<std::vector<double>> read_numbers(const std::string& path, const edgetrack::FieldRange& range) {
  auto words = edgetrack::read_words(path);
  if (!words.ok()) return words.error();
  std::vector<double> numbers;
  for (const edgetrack::Word& word : words.value()) {
    auto value = edgetrack::parse_field(word.text, range, path, word.line);
    if (!value.ok()) return value.error();
    numbers.push_back(value.value());
  }
  return numbers;
}

/// 3x3 inverse in double (set-up code); false when singular relative to its scale.
bool invert(const double m[3][3], double inv[3][3]) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  double scale = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) scale = std::fmax(scale, std::fabs(m[r][c]));
  if (std::fabs(det) <= 1e-9 * scale * scale * scale) return false;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      inv[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
    }
  return true;
}

/// Reprojection residuals around a start pose: x = (v, w), the pose start.retract(v, w).
class Reprojection : public vnl_least_squares_function_of<real> {
 public:
  Reprojection(const std::vector<Vec3>& points, const std::vector<Vec2>& pixels, const PinholeCamera& camera,
               const Se3& start)
      : vnl_least_squares_function_of<real>(6, static_cast<unsigned>(2 * points.size()), no_gradient),
        points_(points),
        pixels_(pixels),
        camera_(camera),
        start_(start) {}

  Se3 pose(const vnl_vector<real>& x) const {
    return start_.retract(Vec3{x[0], x[1], x[2]}, Vec3{x[3], x[4], x[5]});
  }

  void f(const vnl_vector<real>& x, vnl_vector<real>& fx) override {
    const Se3 p = pose(x);
    for (size_t i = 0; i < points_.size(); ++i) {
      const Vec3 c = p * points_[i];
      if (c.z <= real(0.001)) {
        throw_failure();
        return;
      }
      const Vec2 q = camera_.project(c);
      fx[static_cast<unsigned>(2 * i)] = q.x - pixels_[i].x;
      fx[static_cast<unsigned>(2 * i + 1)] = q.y - pixels_[i].y;
    }
  }

 private:
  const std::vector<Vec3>& points_;
  const std::vector<Vec2>& pixels_;
  PinholeCamera camera_;
  Se3 start_;
};

}  // namespace

Result<std::vector<Vec3>> read_init_points(const std::string& path) {
  auto words = edgetrack::read_words(path);
  if (!words.ok()) return words.error();
  const std::vector<edgetrack::Word>& w = words.value();
  if (w.empty()) return Error{path, 0, "empty file (expected the number of points, then X Y Z per point)"};
  auto count = edgetrack::parse_whole_field(w[0].text, {"the number of points", 1, kMaxInitPoints}, path, w[0].line);
  if (!count.ok()) return count.error();
  const size_t n = static_cast<size_t>(count.value());
  if (w.size() != 1 + 3 * n)
    return Error{path, w.back().line, "expected " + std::to_string(n) + " points of 3 numbers after the count, found " +
                                          std::to_string(w.size() - 1) + " numbers"};
  static const char* const kAxes[3] = {"X (m)", "Y (m)", "Z (m)"};
  std::vector<Vec3> points(n);
  for (size_t i = 0; i < n; ++i) {
    real xyz[3];
    for (int k = 0; k < 3; ++k) {
      const edgetrack::Word& word = w[1 + 3 * i + k];
      auto value = edgetrack::parse_field(word.text, {kAxes[k], -kMaxPointCoordinate, kMaxPointCoordinate}, path,
                                          word.line);
      if (!value.ok()) return value.error();
      xyz[k] = real(value.value());
    }
    points[i] = {xyz[0], xyz[1], xyz[2]};
  }
  return points;
}

Result<std::vector<Vec2>> read_image_points(const std::string& path) {
  auto numbers = read_numbers(path, {"a pixel coordinate", -kMaxPixelCoordinate, kMaxPixelCoordinate});
  if (!numbers.ok()) return numbers.error();
  const std::vector<double>& n = numbers.value();
  if (n.empty() || n.size() % 2 != 0)
    return Error{path, 0, "expected pairs 'u v' of pixel coordinates, found " + std::to_string(n.size()) + " numbers"};
  std::vector<Vec2> pixels;
  for (size_t i = 0; i < n.size(); i += 2) pixels.push_back({real(n[i]), real(n[i + 1])});
  return pixels;
}

Result<PointPose> pose_from_points(const std::vector<Vec3>& points_in_model, const std::vector<Vec2>& pixels,
                                   const PinholeCamera& camera, const std::string& source) {
  const size_t n = points_in_model.size();
  if (pixels.size() != n)
    return Error{source, 0, std::to_string(n) + " 3D points but " + std::to_string(pixels.size()) + " image points"};
  if (n < 4) return Error{source, 0, "at least 4 points are needed, found " + std::to_string(n)};
  // POSIT (set-up code, in double): object vectors from point 0, their pseudo-inverse B.
  std::vector<std::array<double, 3>> a(n);
  std::vector<double> x(n), y(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec3 d = points_in_model[i] - points_in_model[0];
    a[i] = {static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z)};
    x[i] = static_cast<double>((pixels[i].x - camera.u0) / camera.px);
    y[i] = static_cast<double>((pixels[i].y - camera.v0) / camera.py);
  }
  double ata[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, inv[3][3];
  for (size_t i = 1; i < n; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) ata[r][c] += a[i][r] * a[i][c];
  if (!invert(ata, inv)) return Error{source, 0, "the 3D points lie in one plane (or a line): 4 points not in one plane are needed"};
  std::vector<double> eps(n, 0.0);
  double rot[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, z0 = 1;
  for (int iteration = 0; iteration < 100; ++iteration) {
    double bi[3] = {0, 0, 0}, bj[3] = {0, 0, 0};
    for (size_t k = 1; k < n; ++k) {
      const double xs = x[k] * (1 + eps[k]) - x[0], ys = y[k] * (1 + eps[k]) - y[0];
      for (int r = 0; r < 3; ++r) {
        bi[r] += a[k][r] * xs;
        bj[r] += a[k][r] * ys;
      }
    }
    double vi[3], vj[3];
    for (int r = 0; r < 3; ++r) {
      vi[r] = inv[r][0] * bi[0] + inv[r][1] * bi[1] + inv[r][2] * bi[2];
      vj[r] = inv[r][0] * bj[0] + inv[r][1] * bj[1] + inv[r][2] * bj[2];
    }
    const double ni = std::sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
    const double nj = std::sqrt(vj[0] * vj[0] + vj[1] * vj[1] + vj[2] * vj[2]);
    if (ni <= 0 || nj <= 0) return Error{source, 0, "the image points give no pose (they coincide?)"};
    for (int r = 0; r < 3; ++r) {
      rot[0][r] = vi[r] / ni;
      rot[1][r] = vj[r] / nj;
    }
    rot[2][0] = rot[0][1] * rot[1][2] - rot[0][2] * rot[1][1];
    rot[2][1] = rot[0][2] * rot[1][0] - rot[0][0] * rot[1][2];
    rot[2][2] = rot[0][0] * rot[1][1] - rot[0][1] * rot[1][0];
    z0 = 2 / (ni + nj);
    double change = 0;
    for (size_t k = 1; k < n; ++k) {
      const double e = (a[k][0] * rot[2][0] + a[k][1] * rot[2][1] + a[k][2] * rot[2][2]) / z0;
      change = std::fmax(change, std::fabs(e - eps[k]));
      eps[k] = e;
    }
    if (change < 1e-10) break;
  }
  // The rows i and j are only nearly orthogonal: the rotation log/exp pair projects onto SO(3).
  Mat33 r;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) r.m[row][col] = real(rot[row][col]);
  const Mat33 rotation = edgetrack::rotation_exp(edgetrack::rotation_log(r));
  const Vec3 t0{real(x[0] * z0), real(y[0] * z0), real(z0)};
  const Se3 linear(rotation, t0 - rotation * points_in_model[0]);

  Reprojection residuals(points_in_model, pixels, camera, linear);
  vnl_levenberg_marquardt_of<real> lm(residuals);
  vnl_vector<real> params(6, real(0));
  lm.minimize(params);
  if (residuals.failure) return Error{source, 0, "the points put the model behind the camera"};
  PointPose result;
  result.camera_from_model = residuals.pose(params);
  result.rms_px = static_cast<double>(residuals.rms(params));
  return result;
}

}  // namespace edgetrack_app
