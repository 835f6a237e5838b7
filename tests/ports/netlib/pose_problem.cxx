// SPDX-License-Identifier: BSD-3-Clause
/// Generation of the synthetic pose problems (set-up in double) and the pose error measures.
#include "pose_problem.h"

#include <cmath>
#include <random>

#include "vnl/vnl_rotation_matrix.hxx"

namespace pose_problem {
namespace {

constexpr double kHalfSide = 0.03;  // the 60 mm cube, centred on the model origin
constexpr int kControlPoints = 60;
constexpr double kNoisePx = 0.3;
constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxStartRotation = 5 * kPi / 180;
constexpr double kMaxStartTranslation = 0.005;

/// Uniform in (0, 1) from mt19937's 32 bits (fully specified, so identical on every platform).
double uniform(std::mt19937& random) { return (static_cast<double>(random()) + 0.5) / 4294967296.0; }

double gaussian(std::mt19937& random) {
  const double r = std::sqrt(-2 * std::log(uniform(random)));
  return r * std::cos(2 * kPi * uniform(random));
}

Vec3 random_unit_vector(std::mt19937& random) {
  Vec3 v(gaussian(random), gaussian(random), gaussian(random));
  return v.normalize();
}

Vec3 axis_vector(int axis, double value) {
  Vec3 v;
  v[axis] = value;
  return v;
}

}  // namespace

Problem generate(std::uint32_t seed) {
  std::mt19937 random(seed);
  Problem p;
  p.truth.rotation = vnl_rotation_matrix(random_unit_vector(random) * (kPi * uniform(random)));
  p.truth.translation = Vec3(0.02 * uniform(random) - 0.01, 0.02 * uniform(random) - 0.01, 0.15);

  // Visible faces: facing the camera by more than ~6 degrees. The camera centre in the model
  // frame is -R^T t.
  const Vec3 camera_in_model = -(p.truth.rotation.transpose() * p.truth.translation);
  bool visible[3][2];  // [axis][0: -, 1: +]
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const Vec3 normal = axis_vector(axis, side ? 1 : -1);
      const Vec3 to_camera = (camera_in_model - normal * kHalfSide).normalize();
      visible[axis][side] = dot_product(normal, to_camera) > 0.1;
    }
  }
  // An edge of the cube lies along `axis` at the other two coordinates +-half side; it is
  // visible when one of its two faces is.
  struct Edge {
    Vec3 from, direction;
  };
  std::vector<Edge> edges;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int sa = 0; sa < 2; ++sa) {
      for (int sb = 0; sb < 2; ++sb) {
        if (!visible[a][sa] && !visible[b][sb]) continue;
        const Vec3 from = axis_vector(a, sa ? kHalfSide : -kHalfSide) + axis_vector(b, sb ? kHalfSide : -kHalfSide) +
                          axis_vector(axis, -kHalfSide);
        edges.push_back({from, axis_vector(axis, 1)});
      }
    }
  }

  // Control points evenly spread over the visible edges' total length.
  const double step = 2 * kHalfSide * static_cast<double>(edges.size()) / kControlPoints;
  for (int k = 0; k < kControlPoints; ++k) {
    const double s = (k + 0.5) * step;
    const Edge& edge = edges[static_cast<std::size_t>(s / (2 * kHalfSide))];
    const double along = s - 2 * kHalfSide * std::floor(s / (2 * kHalfSide));
    ControlPoint c;
    c.point_in_model = edge.from + edge.direction * along;
    const Vec3 x = p.truth.rotation * c.point_in_model + p.truth.translation;
    const Vec3 d = p.truth.rotation * edge.direction;
    const double u = p.u0 + p.px * x[0] / x[2];
    const double v = p.v0 + p.py * x[1] / x[2];
    // The projected edge direction (d(u, v)/dX * d) and its unit normal.
    const double du = p.px * (d[0] - x[0] * d[2] / x[2]) / x[2];
    const double dv = p.py * (d[1] - x[1] * d[2] / x[2]) / x[2];
    const double length = std::hypot(du, dv);
    c.n[0] = -dv / length;
    c.n[1] = du / length;
    const double noise = kNoisePx * gaussian(random);
    c.q[0] = u + noise * c.n[0];
    c.q[1] = v + noise * c.n[1];
    p.points.push_back(c);
  }

  p.start.rotation =
      vnl_rotation_matrix(random_unit_vector(random) * (kMaxStartRotation * uniform(random))) * p.truth.rotation;
  p.start.translation = p.truth.translation + random_unit_vector(random) * (kMaxStartTranslation * uniform(random));
  return p;
}

Pose pose_from_parameters(const Problem& problem, const double x[6]) {
  Pose pose;
  pose.rotation = vnl_rotation_matrix(Vec3(x[0], x[1], x[2])) * problem.start.rotation;
  pose.translation = Vec3(x[3], x[4], x[5]) / problem.units_per_metre;
  return pose;
}

double rotation_error_deg(const Pose& a, const Pose& b) {
  return vnl_rotation_thetau(Mat33(a.rotation * b.rotation.transpose())).two_norm() * 180 / kPi;
}

double translation_error_mm(const Pose& a, const Pose& b) { return (a.translation - b.translation).two_norm() * 1000; }

}  // namespace pose_problem
